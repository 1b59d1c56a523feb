#include "sim/runner/run_directory.h"

#include <gtest/gtest.h>

#include <fstream>

#include "sim/config/config_error.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::sim {
namespace {

namespace fs = std::filesystem;
using testing::MakeTempDir;
using testing::WriteFile;

TEST(RunDirectoryTest, AbsentOrEmptyDirectoriesAreReadyAsTheyAre) {
  const fs::path dir = MakeTempDir("run_directory_empty");
  EXPECT_NO_THROW(PrepareRunDirectory(dir / "absent", false));
  EXPECT_FALSE(fs::exists(dir / "absent"));
  EXPECT_NO_THROW(PrepareRunDirectory(dir, false));
}

TEST(RunDirectoryTest, AnEarlierRunIsReplacedOnlyWithForce) {
  const fs::path dir = MakeTempDir("run_directory_earlier");
  WriteFile(dir / "config.yaml", "name: small\nseed: 1\n");
  WriteFile(dir / "metrics.json", "{}\n");
  WriteFile(dir / "laser_hits.csv", "1,2\n");  // an earlier run's file the new one may not write
  WriteFile(dir / "trajectory.ekf.tum", "0 0 0 0 0 0 0 1\n");
  WriteFile(dir / "before" / "cw_1" / "metrics.json", "{}\n");
  EXPECT_TRUE(HoldsPlywoodRun(dir));
  try {
    PrepareRunDirectory(dir, false);
    FAIL() << "an earlier run was accepted without --force";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(dir.string() + ": already holds an earlier run"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(fs::exists(dir / "laser_hits.csv"));
  PrepareRunDirectory(dir, true);
  EXPECT_TRUE(fs::is_directory(dir));
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(RunDirectoryTest, ForceRefusesARunFolderThatAlsoHoldsAUsersFiles) {
  const fs::path dir = MakeTempDir("run_directory_mixed");
  // An experiment file named config.yaml beside the user's own work (the reviewer's case), and a
  // run directory the user put an estimate and notes into.
  WriteFile(dir / "proj" / "config.yaml", "name: mine\nseed: 1\n");
  WriteFile(dir / "proj" / "thesis.tex", "x\n");
  EXPECT_FALSE(HoldsPlywoodRun(dir / "proj"));  // no metrics.json: not a run
  EXPECT_THROW(PrepareRunDirectory(dir / "proj", true), ConfigError);
  WriteFile(dir / "run" / "config.yaml", "name: small\nseed: 1\n");
  WriteFile(dir / "run" / "metrics.json", "{}\n");
  WriteFile(dir / "run" / "my_estimate.tum", "0 0 0 0 0 0 0 1\n");
  WriteFile(dir / "run" / "notes" / "todo.txt", "score it\n");
  try {
    PrepareRunDirectory(dir / "run", true);
    FAIL() << "a user's file would have been deleted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("which no run writes"), std::string::npos) << e.what();
  }
  for (const char* kept : {"proj/config.yaml", "proj/thesis.tex", "run/my_estimate.tum",
                           "run/notes/todo.txt", "run/metrics.json"}) {
    EXPECT_TRUE(fs::exists(dir / kept)) << kept;
  }
}

TEST(RunDirectoryTest, OtherFilesAreNeverDeletedEvenWithForce) {
  const fs::path dir = MakeTempDir("run_directory_foreign");
  WriteFile(dir / "thesis.tex", "\\documentclass{article}\n");
  // A config.yaml of some other tool is not a run either.
  WriteFile(dir / "other" / "config.yaml", "database: {host: localhost}\n");
  for (const fs::path& d : {dir, dir / "other"}) {
    SCOPED_TRACE(d.string());
    EXPECT_FALSE(HoldsPlywoodRun(d));
    EXPECT_THROW(PrepareRunDirectory(d, true), ConfigError);
  }
  EXPECT_TRUE(fs::exists(dir / "thesis.tex"));
  EXPECT_TRUE(fs::exists(dir / "other" / "config.yaml"));
  // A file where the directory should be.
  EXPECT_THROW(PrepareRunDirectory(dir / "thesis.tex", true), ConfigError);
  EXPECT_TRUE(fs::exists(dir / "thesis.tex"));
}

}  // namespace
}  // namespace plywood::sim
