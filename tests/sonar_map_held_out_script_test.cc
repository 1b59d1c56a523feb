// scripts/sonar_map_held_out, the command behind docs/sonar_map.md's held-out table: its figures
// on hand-made sweep folders whose mean, nearest-rank p90, worst and counts are known, and its
// refusal of a folder that holds no finished sweep.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "plywood_paths.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;
using testing::MakeTempDir;
using testing::WriteFile;

// The script's exit code, stdout and stderr, as the CLI tests read plywood's.
using ScriptResult = testing::CliResult;

ScriptResult RunTable(const fs::path& out, const std::string& seeds) {
  return testing::RunScript(out, "sonar_map_held_out",
                            "--table-only --out " + out.string() + " --seeds " + seeds);
}

ScriptResult RunScript(const fs::path& out, const std::string& args) {
  return testing::RunScript(out, "sonar_map_held_out", args);
}

// A finished sweep's results.csv with the columns the table reads (and one it does not), and its
// manifest's cells.csv: `cells` cells (by default one per row of results.csv).
void WriteSweep(const fs::path& folder, const std::string& rows, int cells = -1) {
  fs::create_directories(folder);
  WriteFile(folder / "results.csv",
            "id,world,seed,occupancy.error,occupancy.grid_error,sensors.bumpers.contact_samples,"
            "occupancy.error_without_narrow_gaps\n" +
                rows);
  if (cells < 0) cells = static_cast<int>(std::count(rows.begin(), rows.end(), '\n'));
  std::string manifest = "index,id,world,seed\n";
  for (int i = 0; i < cells; ++i)
    manifest += std::to_string(i) + ",c" + std::to_string(i) + ",w,1\n";
  WriteFile(folder / "cells.csv", manifest);
}

void ExpectOneLineNaming(const ScriptResult& r, const std::string& text) {
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(r.err.find("Traceback"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(text), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_EQ(r.out.find("| generator seed"), std::string::npos) << r.out;  // no half table
}

TEST(SonarMapHeldOutScriptTest, TabulatesEachSweepPoolsThemAndReadsRoomsByTheirMeans) {
  const fs::path dir = MakeTempDir("SonarMapHeldOut");
  // Generator seed 1: e 0.01 / 0.03 (room w0), 0.12 / 0.10 (room w1, mean 0.11): mean 0.065,
  // nearest-rank p90 of four runs the 4th smallest (0.12), one run above 0.10 (0.10 is not);
  // without the narrow gaps 0.01 / 0.01 / 0.02 / 0.04: mean 0.02, p90 0.04, meets the bar.
  WriteSweep(dir / "g1-net",
             "a,w0.xml,1,0.01,0.5,0,0.01\n"
             "b,w0.xml,2,0.03,0.5,3,0.01\n"
             "c,w1.xml,1,0.12,0.5,0,0.02\n"
             "d,w1.xml,2,0.10,0.5,0,0.04\n");
  // Generator seed 2: its own room w0 (the same file name in another sweep is another room).
  WriteSweep(dir / "g2-net",
             "e,w0.xml,1,0.02,0.5,0,0.02\n"
             "f,w0.xml,2,0.02,0.5,0,0.02\n");
  const ScriptResult r = RunTable(dir, "1,2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("| 1 | 0.0650 / 0.1200 / 0.1200 / 1 | 0.0200 / 0.0400 / 0.0400 / 0 | 1 | "
                       "fails / meets |"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("| 2 | 0.0200 / 0.0200 / 0.0200 / 0 | 0.0200 / 0.0200 / 0.0200 / 0 | 0 | "
                       "meets / meets |"),
            std::string::npos)
      << r.out;
  // Pooled: six runs, e mean 0.30 / 6, p90 the 6th smallest (ceil(5.4)).
  EXPECT_NE(r.out.find("| pooled (6 runs) | 0.0500 / 0.1200 / 0.1200 / 1 | "
                       "0.0200 / 0.0400 / 0.0400 / 0 | 1 | |"),
            std::string::npos)
      << r.out;
  // Rooms: seed 1's w1 (0.11) is the one above 0.10 with e; none without the narrow gaps.
  EXPECT_NE(r.out.find("above 0.1, e: 1 of 3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("above 0.1, without narrow gaps: 0 of 3"), std::string::npos) << r.out;
}

TEST(SonarMapHeldOutScriptTest, AFolderWithoutAFinishedSweepIsNamedInOneLine) {
  const fs::path dir = MakeTempDir("SonarMapHeldOutMissing");
  WriteSweep(dir / "g1-net", "a,w0.xml,1,0.01,0.5,0,0.01\n");
  const ScriptResult r = RunTable(dir, "1,5");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(r.err.find("Traceback"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find((dir / "g5-net" / "results.csv").string()), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

// s63 (forty-seventh pass): results.csv holds only a sweep's finished runs, so a sweep with failed
// runs (plywood sweep exits 1, failures.csv) or one killed and then collected was tabulated as if
// whole, under its generator seed, exit 0; a seed listed twice counted its runs twice in the pooled
// figures and the rooms; a run without a number was sorted as NaN.
TEST(SonarMapHeldOutScriptTest, ASweepMissingRunsOrASeedListedTwiceIsNotTabulated) {
  const fs::path dir = MakeTempDir("SonarMapHeldOutPartial");
  WriteSweep(dir / "g1-net", "a,w0.xml,1,0.01,0.5,0,0.01\n", 3);
  WriteFile(dir / "g1-net" / "failures.csv", "id,exit_code,error\nc1,2,plywood: x\n");
  ExpectOneLineNaming(RunTable(dir, "1"), (dir / "g1-net" / "results.csv").string() +
                                              ": holds 1 of the sweep's 3 runs (1 failed, in "
                                              "failures.csv; 1 unfinished)");
  WriteSweep(dir / "g2-net", "a,w0.xml,1,0.01,0.5,0,0.01\n");
  ExpectOneLineNaming(RunTable(dir, "2,2"), "--seeds: 2 is listed twice");
  ExpectOneLineNaming(RunTable(dir, "-2"), "--seeds: -2: a generator seed is a whole number >= 0");
  ExpectOneLineNaming(RunTable(dir, "10000000000000000000"),
                      "--seeds: 10000000000000000000: a generator seed is a whole number >= 0 of "
                      "at most 19 digits");
  // A run without a number (an empty cell) gave `nan` for the mean beside a p90 and worst of a
  // list sorted with a NaN in it, and its room left out of the rooms above the bar.
  WriteSweep(dir / "g3-net",
             "a,w0.xml,1,0.01,0.5,0,0.01\n"
             "b,w1.xml,1,,0.5,0,0.01\n"
             "c,w1.xml,2,0.2,0.5,0,0.01\n");
  ExpectOneLineNaming(RunTable(dir, "3"), (dir / "g3-net" / "results.csv").string() +
                                              ": line 3 (run b): occupancy.error: expected a "
                                              "number, got ''");
  // A results.csv without the sweep's manifest beside it is no sweep's.
  fs::remove(dir / "g2-net" / "cells.csv");
  ExpectOneLineNaming(RunTable(dir, "2"), (dir / "g2-net" / "cells.csv").string());
}

// s63 (forty-seventh pass): a --build without apps/plywood, an --out under a file and a negative
// --jobs stopped with a Python traceback (or plywood's line and then the script's).
TEST(SonarMapHeldOutScriptTest, AMissingProgramAnUnwritableOutOrNegativeJobsIsNamedInOneLine) {
  const fs::path dir = MakeTempDir("SonarMapHeldOutFlags");
  WriteFile(dir / "a_file", "not a folder\n");
  ExpectOneLineNaming(
      RunScript(dir, "--seeds 1 --build " + (dir / "nobuild").string() + " --out " +
                         (dir / "o").string()),
      "--build: " + (dir / "nobuild" / "apps" / "plywood").string() + ": no such program");
  ExpectOneLineNaming(RunScript(dir, "--seeds 1 --build " + fs::path(PLYWOOD_BINARY_DIR).string() +
                                         " --out " + (dir / "a_file" / "o").string()),
                      "--out: " + (dir / "a_file" / "o").string() + ": cannot write");
  ExpectOneLineNaming(RunScript(dir, "--seeds 1 --jobs -1 --out " + (dir / "o").string()),
                      "--jobs: must be >= 0");
  EXPECT_FALSE(fs::exists(dir / "o"));
}

// s66 (fifty-sixth pass): an unknown flag, a --model of no model or a --jobs of no number was
// argparse's usage and its error, four lines.
TEST(SonarMapHeldOutScriptTest, AnUnknownFlagOrAValueOfNoChoiceIsNamedInOneLine) {
  const fs::path dir = MakeTempDir("SonarMapHeldOutUsage");
  ExpectOneLineNaming(RunScript(dir, "--table-only --sedes 60"),
                      "sonar_map_held_out: unrecognized arguments: --sedes 60");
  ExpectOneLineNaming(RunScript(dir, "--table-only --model cnn"),
                      "sonar_map_held_out: argument --model: invalid choice: 'cnn'");
  ExpectOneLineNaming(RunScript(dir, "--table-only --jobs x"),
                      "sonar_map_held_out: argument --jobs: invalid int value: 'x'");
}

}  // namespace
}  // namespace plywood
