// The shipped scripts that read one run's folder or run plywood themselves
// (scripts/encoder_transient_calibration, stop_displacement_calibration, line_worlds_table,
// sonar_map_worlds_table, odometry_table, check_generated_worlds) given bad input (s66 fifty-sixth
// pass): one line naming the file and the field (or the argument), exit 2, never a traceback,
// never a figure of half a run or a pass of no test. Every refusal here comes before any run.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <tuple>

#include "plywood_paths.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing::MakeTempDir;
using testing::PythonImports;
using testing::RunScript;
using testing::Slurp;
using testing::SourceRoot;
using testing::WriteFile;

void ExpectRefusal(const CliResult& r, const std::string& text) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err.find("Traceback"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(text), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_EQ(r.out.find("odometry.ekf."), std::string::npos) << r.out;  // no calibrated value
}

// A calibration run's folder as plywood run writes it: a hard braking at 0.2 s (both wheels from
// 0.4 m/s to rest in one tenth of a second), so both scripts find what they measure.
void WriteRun(const fs::path& run, bool finished, const std::string& encoder_ticks = "63") {
  WriteFile(run / "config.yaml",
            "robot:\n  nominal:\n    wheel_radius_m: 0.0975\n    track_m: 0.33\n"
            "    encoder_ticks_per_rev: 39000\n");
  WriteFile(run / "trajectory.csv",
            "time_s,truth_x_m,truth_y_m,truth_theta_rad\n0,0,0,0\n0.1,0.04,0,0\n0.2,0.08,0,0\n"
            "0.3,0.08,0,0.01\n");
  WriteFile(run / "encoders.csv", "time_s,left_ticks,right_ticks\n0,0,0\n0.1," + encoder_ticks +
                                      ",63\n0.2,126,126\n0.3,126,136\n");
  if (finished) WriteFile(run / "complete.json", "{\"files\": {}}\n");
}

// Both calibrations measured a run killed half way (no complete.json) as if whole, and a missing
// folder, a tick count that is no number or a python3 without yaml was a traceback.
void CheckCalibrationRefusals(const std::string& script) {
  if (!PythonImports()) GTEST_SKIP() << "python3 is not installed";
  const fs::path dir = MakeTempDir(script);
  WriteRun(dir / "killed", false);
  WriteRun(dir / "text", true, "sixty");
  ExpectRefusal(RunScript(dir, script, "nowhere"), script + ": nowhere: no such folder");
  ExpectRefusal(RunScript(dir, script, "killed"),
                script + ": killed: not a finished run: no complete.json");
  // python3 -S leaves out the packages Debian installs, python3-yaml among them.
  ExpectRefusal(RunScript(dir, script, "killed", "/usr/bin/python3 -S"),
                script + ": needs python3-yaml");
  if (!PythonImports("yaml")) GTEST_SKIP() << "python3-yaml is not installed";
  ExpectRefusal(RunScript(dir, script, "text"),
                script +
                    ": text/encoders.csv: line 3: left_ticks: expected a whole number, got "
                    "'sixty'");
}

TEST(RunScriptsTest, EncoderTransientCalibrationRefusesRunsNotFinishedAndTextTicks) {
  CheckCalibrationRefusals("encoder_transient_calibration");
}

TEST(RunScriptsTest, StopDisplacementCalibrationRefusesRunsNotFinishedAndTextTicks) {
  CheckCalibrationRefusals("stop_displacement_calibration");
}

// The world tables took a FIRST or LAST that is no number to sh's "Illegal number", made no world
// and ended in a traceback from a table of nothing (line_worlds_table) or two lines of sh
// (sonar_map_worlds_table); odometry_table's missing plywood was sh's "not found", exit 127.
TEST(RunScriptsTest, WorldTablesAndTheOdometryTableRefuseArgumentsBeforeAnyRun) {
  if (!PythonImports()) GTEST_SKIP() << "python3 is not installed";
  const fs::path dir = MakeTempDir("WorldTablesBadInput");
  const std::string build = PLYWOOD_BINARY_DIR;
  ExpectRefusal(RunScript(dir, "line_worlds_table", "abc 1 split_and_merge " + build + " 1 room"),
                "line_worlds_table: FIRST: expected a whole number >= 0 of at most 9 digits, got "
                "'abc'");
  ExpectRefusal(RunScript(dir, "sonar_map_worlds_table", "0 x " + build),
                "sonar_map_worlds_table: LAST: expected a whole number >= 0 of at most 9 digits, "
                "got 'x'");
  ExpectRefusal(RunScript(dir, "sonar_map_worlds_table", "0 1 " + build + " -3"),
                "sonar_map_worlds_table: SEED: expected a whole number >= 0");
  ExpectRefusal(
      RunScript(dir, "line_worlds_table", "0 1 split_and_merge " + (dir / "nobuild").string()),
      "line_worlds_table: BUILD_DIR: " + (dir / "nobuild" / "apps" / "plywood").string() +
          ": no such program");
  ExpectRefusal(RunScript(dir, "odometry_table", (dir / "nobuild").string()),
                "odometry_table: BUILD_DIR: " + (dir / "nobuild" / "apps" / "plywood").string() +
                    ": no such program");
}

// scripts/alternate_runs (s67): whole `plywood run` processes of binaries taking turns, min /
// median / max wall ms each. Its refusals come before any run; a run that fails ends it, naming
// the binary and the run's own line.
TEST(RunScriptsTest, AlternateRunsTimesEachBinaryAndRefusesBadArgumentsBeforeAnyRun) {
  if (!PythonImports()) GTEST_SKIP() << "python3 is not installed";
  const fs::path dir = MakeTempDir("AlternateRuns");
  const std::string plywood = std::string(PLYWOOD_BINARY_DIR) + "/apps/plywood";
  const std::string experiment = (SourceRoot() / "experiments" / "default.yaml").string();
  ExpectRefusal(RunScript(dir, "alternate_runs", "nope.yaml " + plywood),
                "alternate_runs: EXPERIMENT: nope.yaml: no such file");
  ExpectRefusal(RunScript(dir, "alternate_runs", experiment + " " + (dir / "none").string()),
                "alternate_runs: BINARY: " + (dir / "none").string() + ": no such file");
  ExpectRefusal(RunScript(dir, "alternate_runs", "--runs 0 " + experiment + " " + plywood),
                "alternate_runs: --runs: expected a whole number in [1, 1000], got '0'");
  ExpectRefusal(RunScript(dir, "alternate_runs", "--set x " + experiment + " " + plywood),
                "alternate_runs: --set: expected KEY=VALUE, got 'x'");
  ExpectRefusal(RunScript(dir, "alternate_runs", experiment + " " + plywood + " " + plywood),
                "alternate_runs: BINARY: a binary given twice");
  ExpectRefusal(RunScript(dir, "alternate_runs", experiment), "expected EXPERIMENT and at least");

  // One short round: the table names the binary with three wall times.
  const CliResult ran =
      RunScript(dir, "alternate_runs", "--runs 1 --set duration_s=2 " + experiment + " " + plywood);
  ASSERT_EQ(ran.exit_code, 0) << ran.err;
  EXPECT_NE(ran.out.find("| " + plywood + " | "), std::string::npos) << ran.out;
  EXPECT_NE(ran.out.find("(1 runs each)"), std::string::npos) << ran.out;
  // A run that fails ends the script with its own line.
  const CliResult failed =
      RunScript(dir, "alternate_runs", "--runs 1 --set robot.nope=1 " + experiment + " " + plywood);
  EXPECT_EQ(failed.exit_code, 1);
  EXPECT_NE(failed.err.find("round 1 exited 2: plywood: "), std::string::npos) << failed.err;
  EXPECT_NE(failed.err.find("robot.nope: unknown key"), std::string::npos) << failed.err;
}

// check_generated_worlds with a family no test has ran no test and passed (exit 0); a SEED that is
// no number was a test failure amid gtest's output, the worlds then checked with seed 1.
TEST(RunScriptsTest, CheckGeneratedWorldsRefusesAFamilyNoTestHasAndSeedsThatAreNoNumbers) {
  const fs::path dir = MakeTempDir("CheckWorldsBadInput");
  const std::string build = PLYWOOD_BINARY_DIR;
  if (!fs::exists(fs::path(build) / "sim" / "sim.generated_worlds_test"))
    GTEST_SKIP() << "sim.generated_worlds_test is not built";
  ExpectRefusal(RunScript(dir, "check_generated_worlds", "1 2 " + build + " rooms"),
                "check_generated_worlds: FAMILY: no family 'rooms'");
  ExpectRefusal(RunScript(dir, "check_generated_worlds", "abc 2 " + build + " room"),
                "check_generated_worlds: SEED: expected a whole number in [0, 1000000], got 'abc'");
  ExpectRefusal(RunScript(dir, "check_generated_worlds", "1 0 " + build + " room"),
                "check_generated_worlds: COUNT: expected a whole number in [1, 1000000], got '0'");
}

// scripts/demo and scripts/test ignored any argument (`scripts/test -R sweep`, `scripts/demo
// --help`): they installed packages, built and ran everything. Each is run from a copy of scripts/
// whose setup only leaves a mark, so the test never installs or builds.
TEST(RunScriptsTest, DemoAndTestRefuseArgumentsBeforeTheyInstallOrBuild) {
  const fs::path dir = MakeTempDir("DemoAndTestArguments");
  const fs::path mark = dir / "setup_ran";
  WriteFile(dir / "tree" / "scripts" / "setup",
            "#!/bin/sh\ntouch '" + mark.string() + "'\nexit 1\n");
  for (const std::string script : {"demo", "test"}) {
    fs::copy_file(SourceRoot() / "scripts" / script, dir / "tree" / "scripts" / script,
                  fs::copy_options::overwrite_existing);
  }
  fs::permissions(dir / "tree" / "scripts", fs::perms::owner_all, fs::perm_options::add);
  for (const auto& e : fs::directory_iterator(dir / "tree" / "scripts"))
    fs::permissions(e.path(), fs::perms::owner_exec, fs::perm_options::add);
  for (const auto& [script, arg, first] :
       {std::tuple{"demo", "--help", "--help"}, std::tuple{"test", "-R sweep", "-R"}}) {
    SCOPED_TRACE(script);
    const std::string command = "'" + (dir / "tree" / "scripts" / script).string() + "' " + arg +
                                " >'" + (dir / "stdout").string() + "' 2>'" +
                                (dir / "stderr").string() + "'";
    const int status = std::system(command.c_str());
    const CliResult r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, Slurp(dir / "stdout"),
                      Slurp(dir / "stderr")};
    ExpectRefusal(r, std::string(script) + ": '" + first + "': takes no arguments");
    EXPECT_FALSE(fs::exists(mark)) << "setup ran";
  }
}

// scripts/fresh_debian_check removes its --dir whole at the end (rm -rf): an existing folder's
// files went with it, and a relative --dir was taken inside the tree (the script cds there first)
// rather than where the caller stands (s66 review). Each --dir is refused before anything is
// installed, mounted or fetched; the mirror is one nothing answers, so a check that went ahead
// would fail at once (and remove the folder).
TEST(RunScriptsTest, FreshDebianCheckRefusesAFolderItWouldRemoveThatIsNotItsOwn) {
  const fs::path dir = MakeTempDir("FreshDebianCheckDir");
  WriteFile(dir / "victim" / "keep.txt", "precious\n");
  const std::string mirror = " --mirror http://127.0.0.1:1/debian";
  ExpectRefusal(
      RunScript(dir, "fresh_debian_check", "--dir '" + (dir / "victim").string() + "'" + mirror),
      "fresh_debian_check: --dir " + (dir / "victim").string() +
          ": exists and is not an empty folder");
  ASSERT_TRUE(fs::exists(dir / "victim" / "keep.txt")) << "the folder's files were removed";
  // Relative to where it is called from, not to the tree.
  ExpectRefusal(RunScript(dir, "fresh_debian_check", "--dir victim" + mirror),
                "--dir " + (dir / "victim").string() + ": exists and is not an empty folder");
  ExpectRefusal(
      RunScript(dir, "fresh_debian_check",
                "--dir '" + (SourceRoot() / "debian-root").string() + "'" + mirror),
      "--dir " + fs::weakly_canonical(SourceRoot() / "debian-root").string() + ": inside the tree");
  EXPECT_FALSE(fs::exists(SourceRoot() / "debian-root"));
  EXPECT_TRUE(fs::exists(dir / "victim" / "keep.txt"));
}

}  // namespace
}  // namespace plywood
