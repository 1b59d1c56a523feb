// The process environment a lab's machine or cluster gives plywood (docs/errors.md, the s65
// fifty-fourth pass): stack and memory limits, few file descriptors, standard streams closed, full
// or read by a pipe that closes early, a matplotlib that cannot write its cache. Each test sets the
// limit or stream in a child shell of its own and skips, saying why, where the machine cannot.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "plywood_paths.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;
using testing::MakeTempDir;
using testing::Slurp;
using testing::SourceRoot;
using testing::WriteFile;

// One second of a robot standing still in the hall, with or without its snapshot.
fs::path StillExperiment(const fs::path& dir, bool snapshot) {
  return WriteFile(
      dir / "still.yaml",
      "name: still\nseed: 1\nduration_s: 1\nworld: " + (SourceRoot() / "worlds/hall.xml").string() +
          "\nrobot: {model: p3dx}\ncontroller: {type: idle}\noutput: {snapshot: " +
          (snapshot ? "true" : "false") + "}\n");
}

// Three runs of it, with a metric to plot.
fs::path ThreeRunSweep(const fs::path& dir) {
  StillExperiment(dir, false);
  return WriteFile(dir / "three.yaml",
                   "experiment: still.yaml\nseeds: [1, 2, 3]\nmetrics: [truth.distance_m]\n");
}

// Runs `script` with bash in `dir`, $PLYWOOD the built binary; its exit status as a shell gives it
// (128 + N for a process killed by signal N).
int RunScript(const fs::path& dir, const std::string& script) {
  const fs::path file = WriteFile(dir / "script.sh", script);
  const std::string command = "cd '" + dir.string() + "' && PLYWOOD='" + PLYWOOD_BINARY_DIR +
                              "/apps/plywood' bash '" + file.string() + "'";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

bool CanSetInAShell(const std::string& limit) {
  return std::system(("bash -c '" + limit + "' 2>/dev/null").c_str()) == 0;
}

bool MatplotlibInstalled() {
  return std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0;
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

int DataLines(const fs::path& csv) {
  const std::vector<std::string> lines = Lines(Slurp(csv));
  return lines.empty() ? 0 : static_cast<int>(lines.size()) - 1;
}

// MuJoCo's mjVFS (2 MB of file-name slots) lay on the stack: under a stack limit below that every
// command that compiles a scene died of SIGSEGV, exit 139, without a line.
TEST(ProcessEnvironmentTest, AStackLimitOfAQuarterMegabyteRuns) {
  if (!CanSetInAShell("ulimit -s 256")) GTEST_SKIP() << "this machine refuses ulimit -s 256";
  const fs::path dir = MakeTempDir("process_environment_stack");
  StillExperiment(dir, false);
  const int status =
      RunScript(dir, "ulimit -s 256\n\"$PLYWOOD\" run still.yaml --out out --quiet 2>err\n");
  EXPECT_EQ(status, 0) << Slurp(dir / "err");
  EXPECT_TRUE(fs::is_regular_file(dir / "out/metrics.json"));
}

// Under `ulimit -v`, MuJoCo's failed allocation read as a world that "does not compile" (exit 2,
// bad input) and a thread that could not start as a bare "Resource temporarily unavailable".
// Every limit from one too small to start the program to one that runs gives a run or one line
// saying what ran out, with the limit.
TEST(ProcessEnvironmentTest, AMemoryLimitIsNamedAndNeverBlamesTheWorld) {
  if (!CanSetInAShell("ulimit -v 100000")) GTEST_SKIP() << "this machine refuses ulimit -v";
  const fs::path dir = MakeTempDir("process_environment_memory");
  StillExperiment(dir, true);
  int refused = 0;
  for (int kb = 20000; kb <= 80000; kb += 5000) {
    const std::string limit = std::to_string(kb);
    fs::remove_all(dir / "out");
    const int status = RunScript(dir, "ulimit -v " + limit +
                                          "\nexec \"$PLYWOOD\" run still.yaml --out out --quiet "
                                          "2>err\n");
    const std::string err = Slurp(dir / "err");
    if (status == 127 && err.find("error while loading shared libraries") != std::string::npos) {
      continue;  // too small for the program to start: the dynamic loader's line, not ours
    }
    if (status == 0) continue;
    ++refused;
    EXPECT_EQ(status, 1) << kb << " kB: " << err;
    EXPECT_EQ(Lines(err).size(), 1u) << kb << " kB: " << err;
    EXPECT_EQ(err.rfind("plywood: error: ", 0), 0u) << err;
    EXPECT_TRUE(err.find("out of memory") != std::string::npos ||
                err.find("cannot start a thread") != std::string::npos)
        << err;
    EXPECT_NE(err.find("(the memory limit, ulimit -v, is " + limit + " kB)"), std::string::npos)
        << err;
    EXPECT_EQ(err.find("does not compile"), std::string::npos) << err;
  }
  EXPECT_GT(refused, 0) << "no limit from 20 to 80 MB stopped the run: the test checked nothing";
}

// `plywood sweep ... 2>&1 | head -1`: the second progress line met a closed pipe and SIGPIPE killed
// the sweep after its first run, its running runs with it (they die with the sweep), and no
// results.csv. Now every run finishes and is recorded; plywood then dies of SIGPIPE, as a program
// whose reader left does, once its files are written.
TEST(ProcessEnvironmentTest, ASweepWhoseReaderLeavesFinishesAndRecordsEveryRun) {
  const fs::path dir = MakeTempDir("process_environment_pipe");
  ThreeRunSweep(dir);
  const int status = RunScript(dir,
                               "\"$PLYWOOD\" sweep three.yaml --out out --jobs 1 2>&1 | head -1 "
                               ">/dev/null\necho ${PIPESTATUS[0]} >status\n");
  ASSERT_EQ(status, 0);
  EXPECT_EQ(Slurp(dir / "status"), "141\n");
  EXPECT_EQ(DataLines(dir / "out/results.csv"), 3) << Slurp(dir / "out/results.csv");
}

// The plot script printed each plot's name into the closed pipe: a BrokenPipeError traceback, the
// plots after the first unmade, and "plotting failed (see above)".
TEST(ProcessEnvironmentTest, APlotScriptWhoseReaderLeftPrintsNoTraceback) {
  if (!MatplotlibInstalled()) GTEST_SKIP() << "python3-matplotlib is not installed";
  const fs::path dir = MakeTempDir("process_environment_plot_pipe");
  ThreeRunSweep(dir);
  ASSERT_EQ(RunScript(dir, "\"$PLYWOOD\" sweep three.yaml --out out 2>err | true\n"), 0);
  const std::string err = Slurp(dir / "err");
  EXPECT_EQ(err.find("Traceback"), std::string::npos) << err;
  EXPECT_EQ(err.find("plotting failed"), std::string::npos) << err;
  EXPECT_TRUE(fs::is_regular_file(dir / "out/plots/truth.distance_m.png"));
}

// With stderr closed (`2>&-`), the sweep's lock file took descriptor 2 and the progress lines were
// written into sweep.lock.
TEST(ProcessEnvironmentTest, AClosedStderrIsNotWrittenIntoTheSweepsFiles) {
  const fs::path dir = MakeTempDir("process_environment_closed");
  ThreeRunSweep(dir);
  EXPECT_EQ(RunScript(dir, "\"$PLYWOOD\" sweep three.yaml --out out >/dev/null 2>&-\n"), 0);
  EXPECT_EQ(Slurp(dir / "out/sweep.lock"), "");
  EXPECT_EQ(DataLines(dir / "out/results.csv"), 3);
}

// `>/dev/full`: the summary (or --version) was lost and plywood exited 0.
TEST(ProcessEnvironmentTest, AStdoutThatCannotBeWrittenIsAnError) {
  const fs::path dir = MakeTempDir("process_environment_full");
  StillExperiment(dir, false);
  EXPECT_EQ(RunScript(dir, "\"$PLYWOOD\" run still.yaml --out out >/dev/full 2>err\n"), 1);
  const std::vector<std::string> lines = Lines(Slurp(dir / "err"));
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines.back(), "plywood: error: stdout: write failed: No space left on device");
  EXPECT_TRUE(fs::is_regular_file(dir / "out/complete.json"));  // the run itself is whole
  EXPECT_EQ(RunScript(dir, "\"$PLYWOOD\" --version >/dev/full 2>err\n"), 1);
  EXPECT_EQ(Slurp(dir / "err").rfind("plywood: error: stdout: write failed", 0), 0u);
}

// The plots went through sh, whose redirections need descriptors above 10: under `ulimit -n 10`
// the sweep said "no plots (python3-matplotlib not installed)" of an installed one.
TEST(ProcessEnvironmentTest, FewFileDescriptorsStillPlot) {
  if (!MatplotlibInstalled()) GTEST_SKIP() << "python3-matplotlib is not installed";
  if (!CanSetInAShell("ulimit -n 10")) GTEST_SKIP() << "this machine refuses ulimit -n 10";
  const fs::path dir = MakeTempDir("process_environment_files");
  ThreeRunSweep(dir);
  EXPECT_EQ(
      RunScript(dir, "ulimit -n 10\n\"$PLYWOOD\" sweep three.yaml --out out >/dev/null 2>err\n"), 0)
      << Slurp(dir / "err");
  const std::string err = Slurp(dir / "err");
  EXPECT_EQ(err.find("not installed"), std::string::npos) << err;
  EXPECT_TRUE(fs::is_regular_file(dir / "out/plots/truth.distance_m.png")) << err;
}

// MPLCONFIGDIR a folder matplotlib may not write in (root's os.access says yes to /sys, so it does
// not fall back to a scratch folder): a 30-line traceback and "plotting failed (see above)".
TEST(ProcessEnvironmentTest, AMatplotlibThatCannotWriteItsCacheIsOneLine) {
  if (!MatplotlibInstalled()) GTEST_SKIP() << "python3-matplotlib is not installed";
  if (geteuid() != 0) {
    GTEST_SKIP() << "needs root: another user's matplotlib falls back to a scratch folder";
  }
  const fs::path dir = MakeTempDir("process_environment_mplconfig");
  ThreeRunSweep(dir);
  EXPECT_EQ(RunScript(dir,
                      "MPLCONFIGDIR=/sys \"$PLYWOOD\" sweep three.yaml --out out --quiet "
                      "2>err\n"),
            1);
  const std::string err = Slurp(dir / "err");
  EXPECT_EQ(Lines(err).size(), 1u) << err;
  EXPECT_EQ(err.rfind("plywood sweep: no plots: matplotlib cannot write its cache: /sys/", 0), 0u)
      << err;
  EXPECT_NE(err.find("(point MPLCONFIGDIR=/sys at a writable folder)"), std::string::npos) << err;
  EXPECT_EQ(DataLines(dir / "out/results.csv"), 3);
}

}  // namespace
}  // namespace plywood
