// scripts/sonar_map_held_out, the command behind docs/sonar_map.md's held-out table: its figures
// on hand-made sweep folders whose mean, nearest-rank p90, worst and counts are known, and its
// refusal of a folder that holds no finished sweep.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;
using testing::MakeTempDir;
using testing::Slurp;
using testing::SourceRoot;
using testing::WriteFile;

struct ScriptResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

ScriptResult RunTable(const fs::path& out, const std::string& seeds) {
  const std::string command = (SourceRoot() / "scripts" / "sonar_map_held_out").string() +
                              " --table-only --out " + out.string() + " --seeds " + seeds + " >" +
                              (out / "stdout").string() + " 2>" + (out / "stderr").string();
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, Slurp(out / "stdout"),
          Slurp(out / "stderr")};
}

// A finished sweep's results.csv with the columns the table reads (and one it does not).
void WriteSweep(const fs::path& folder, const std::string& rows) {
  fs::create_directories(folder);
  WriteFile(folder / "results.csv",
            "id,world,seed,occupancy.error,occupancy.grid_error,sensors.bumpers.contact_samples,"
            "occupancy.error_without_narrow_gaps\n" +
                rows);
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

// s63 review: an empty figure in results.csv read as NaN, which sorted anywhere (p90 and worst
// any run's) and kept its room from ever being "above 0.10"; a sweep with failed runs was
// tabulated without them; a generator seed listed twice was pooled twice. Each exited 0 with a
// table. Each is refused in one line now.
TEST(SonarMapHeldOutScriptTest, AnEmptyFigureAFailedRunOrASeedListedTwiceIsRefused) {
  const fs::path dir = MakeTempDir("SonarMapHeldOutRefusals");
  const auto expect_one_line = [](const ScriptResult& r, const std::string& expected) {
    EXPECT_NE(r.exit_code, 0) << r.out;
    EXPECT_EQ(r.err.find("Traceback"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  };
  WriteSweep(dir / "g1-net",
             "a,w0.xml,1,0.01,0.5,0,0.01\n"
             "b,w0.xml,2,,0.5,0,0.01\n"
             "c,w1.xml,1,0.12,0.5,0,0.02\n");
  expect_one_line(RunTable(dir, "1"), (dir / "g1-net" / "results.csv").string() +
                                          ":3: occupancy.error: '' is not a number (run b)");
  WriteSweep(dir / "g2-net", "a,w0.xml,1,0.01,0.5,0,0.01\n");
  WriteFile(dir / "g2-net" / "failures.csv",
            "id,experiment,world,family,profile,seed,exit_code,error\n"
            "b,e.yaml,w0.xml,seed001,,2,1,diverged\n");
  expect_one_line(RunTable(dir, "2"),
                  (dir / "g2-net" / "failures.csv").string() + ": 1 run(s) failed");
  WriteFile(dir / "g2-net" / "failures.csv",
            "id,experiment,world,family,profile,seed,exit_code,error\n");
  expect_one_line(RunTable(dir, "2,2"), "--seeds: 2 is listed 2 times");
  const ScriptResult once = RunTable(dir, "2");  // the header alone: no run failed
  EXPECT_EQ(once.exit_code, 0) << once.err;
  EXPECT_NE(once.out.find("| pooled (1 runs) |"), std::string::npos) << once.out;
}

}  // namespace
}  // namespace plywood
