#include "sim/runner/run_directory.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "sim/config/config_error.h"
#include "sim/runner/build_id.h"
#include "sim/runner/text_file.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::sim {
namespace {

namespace fs = std::filesystem;
using testing::MakeTempDir;
using testing::WriteFile;

// What a run writes, in `staged`, for the tests below.
void WriteSmallRun(const fs::path& dir, const std::string& name) {
  WriteFile(dir / "config.yaml", "name: " + name + "\nseed: 1\n");
  WriteFile(dir / "metrics.json", "{}\n");
}

TEST(RunDirectoryTest, AnAbsentTargetIsMadeEmptyAndFilledOnlyOnCommit) {
  const fs::path dir = MakeTempDir("run_directory_absent");
  {
    StagedRunDirectory staged(dir / "run/", false);  // a trailing '/' names the same folder
    EXPECT_TRUE(fs::is_directory(dir / "run"));
    EXPECT_TRUE(fs::is_empty(dir / "run"));
    EXPECT_EQ(staged.staging(), dir / ("run.partial-" + std::to_string(getpid())));
    WriteSmallRun(staged.staging(), "small");
    EXPECT_NE(WhyNotAFinishedRun(dir / "run").find("no complete.json"), std::string::npos);
    staged.Commit();
  }
  EXPECT_EQ(WhyNotAFinishedRun(dir / "run"), "");
  EXPECT_FALSE(fs::exists(dir / ("run.partial-" + std::to_string(getpid()))));
  EXPECT_EQ(ReadTextFile(dir / "run" / kRunCompleteFile),
            "{\n  \"files\": {\n    \"config.yaml\": 20,\n    \"metrics.json\": 3\n  },\n"
            "  \"plywood_build_id\": \"" +
                ProgramBuildId() + "\"\n}\n");
}

TEST(RunDirectoryTest, AnUncommittedRunLeavesNothingBehind) {
  const fs::path dir = MakeTempDir("run_directory_uncommitted");
  {
    StagedRunDirectory staged(dir / "run", false);
    WriteSmallRun(staged.staging(), "small");
  }  // a run that threw: no staging folder, no empty target
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(RunDirectoryTest, ATruncatedOrMissingFileIsNotAFinishedRun) {
  const fs::path dir = MakeTempDir("run_directory_truncated");
  WriteSmallRun(dir, "small");
  WriteFile(dir / "laser.log", "FLASER 3 1 2 3\n");
  WriteCompletionRecord(dir);
  EXPECT_EQ(WhyNotAFinishedRun(dir), "");
  WriteFile(dir / "laser.log", "FLASER 3");
  EXPECT_EQ(WhyNotAFinishedRun(dir),
            "laser.log is 8 bytes, complete.json says 15 (truncated or changed after the run)");
  fs::remove(dir / "laser.log");
  EXPECT_EQ(WhyNotAFinishedRun(dir), "laser.log is missing (listed in complete.json)");
  WriteFile(dir / kRunCompleteFile, "{\"files\": ");
  EXPECT_EQ(WhyNotAFinishedRun(dir), "complete.json is not a completion record");
  EXPECT_THROW(RequireFinishedRun(dir), ConfigError);
  EXPECT_EQ(WhyNotAFinishedRun(dir / "absent"), "no such directory");
}

TEST(RunDirectoryTest, AnEarlierRunIsReplacedOnlyWithForceAndOnlyOnCommit) {
  const fs::path dir = MakeTempDir("run_directory_earlier");
  WriteSmallRun(dir, "small");
  WriteFile(dir / "laser_hits.csv", "1,2\n");  // an earlier run's file the new one may not write
  WriteFile(dir / "trajectory.ekf.tum", "0 0 0 0 0 0 0 1\n");
  WriteFile(dir / "before" / "cw_1" / "metrics.json", "{}\n");
  EXPECT_TRUE(HoldsPlywoodRun(dir));
  try {
    StagedRunDirectory staged(dir, false);
    FAIL() << "an earlier run was accepted without --force";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(dir.string() + ": already holds an earlier run"),
              std::string::npos)
        << e.what();
  }
  {
    StagedRunDirectory staged(dir, true);
    WriteSmallRun(staged.staging(), "new");
    // Until the new run commits, the earlier one is whole.
    EXPECT_TRUE(fs::exists(dir / "laser_hits.csv"));
    staged.Commit();
  }
  EXPECT_FALSE(fs::exists(dir / "laser_hits.csv")) << "a file of the earlier run survived";
  EXPECT_FALSE(fs::exists(dir / "before"));
  EXPECT_EQ(ReadTextFile(dir / "config.yaml"), "name: new\nseed: 1\n");
  EXPECT_EQ(WhyNotAFinishedRun(dir), "");
}

TEST(RunDirectoryTest, ForceRefusesARunFolderThatAlsoHoldsAUsersFiles) {
  const fs::path dir = MakeTempDir("run_directory_mixed");
  // An experiment file named config.yaml beside the user's own work (the reviewer's case), and a
  // run directory the user put an estimate and notes into.
  WriteFile(dir / "proj" / "config.yaml", "name: mine\nseed: 1\n");
  WriteFile(dir / "proj" / "thesis.tex", "x\n");
  EXPECT_FALSE(HoldsPlywoodRun(dir / "proj"));  // no metrics.json: not a run
  EXPECT_THROW(StagedRunDirectory(dir / "proj", true), ConfigError);
  WriteSmallRun(dir / "run", "small");
  WriteFile(dir / "run" / "my_estimate.tum", "0 0 0 0 0 0 0 1\n");
  WriteFile(dir / "run" / "notes" / "todo.txt", "score it\n");
  try {
    StagedRunDirectory staged(dir / "run", true);
    FAIL() << "a user's file would have been deleted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("which no run writes"), std::string::npos) << e.what();
  }
  for (const char* kept : {"proj/config.yaml", "proj/thesis.tex", "run/my_estimate.tum",
                           "run/notes/todo.txt", "run/metrics.json"}) {
    EXPECT_TRUE(fs::exists(dir / kept)) << kept;
  }
}

// A picture the finished run's complete.json does not list is the user's, and a subfolder with a
// complete.json of its own another run (docs/geometric_map.md's `--out /tmp/o/S` beside `--out
// /tmp/o`). By name alone both passed as the run's own, and --force deleted them (s63).
TEST(RunDirectoryTest, ForceRefusesAPictureOrARunTheFinishedRunDidNotWrite) {
  const fs::path dir = MakeTempDir("run_directory_unlisted");
  const fs::path run = dir / "run";
  WriteSmallRun(run, "small");
  WriteFile(run / "before" / "cw_1" / "metrics.json", "{}\n");  // a protocol's own run
  WriteCompletionRecord(run);
  WriteFile(run / "timing.json", "{}\n");  // written beside the record, not in it
  const auto expect_refused_naming = [&run](const std::string& foreign) {
    try {
      StagedRunDirectory staged(run, true);
      ADD_FAILURE() << "--force would have deleted " << foreign;
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("also " + foreign), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("which no run writes"), std::string::npos) << e.what();
    }
  };
  WriteFile(run / "my_figure.png", "the user's\n");
  expect_refused_naming("my_figure.png");
  EXPECT_EQ(ReadTextFile(run / "my_figure.png"), "the user's\n");
  fs::remove(run / "my_figure.png");
  WriteSmallRun(run / "seed2", "another");
  WriteCompletionRecord(run / "seed2");
  expect_refused_naming("seed2, ");
  EXPECT_EQ(WhyNotAFinishedRun(run / "seed2"), "");
  fs::remove_all(run / "seed2");
  {  // what the run listed, timing.json and the record itself are replaced as before
    StagedRunDirectory staged(run, true);
    WriteSmallRun(staged.staging(), "new");
    staged.Commit();
  }
  EXPECT_FALSE(fs::exists(run / "before"));
  EXPECT_FALSE(fs::exists(run / "timing.json"));
  EXPECT_EQ(ReadTextFile(run / "config.yaml"), "name: new\nseed: 1\n");
}

// s63 (forty-seventh pass): a complete.json that is there but no completion record (corrupt, or a
// folder of that name) was read as no record at all, so a user's picture passed by its name and a
// file in the folder by its fixed name, and --force deleted both (exit 0). Both are now refused,
// naming the record; a record listing paths outside the folder (../x) deletes nothing there.
TEST(RunDirectoryTest, ForceRefusesAPictureOrFolderAnUnreadableRecordCannotVouchFor) {
  const fs::path dir = MakeTempDir("run_directory_unreadable_record");
  const fs::path run = dir / "run";
  const auto refusal = [&run]() -> std::string {
    try {
      StagedRunDirectory staged(run, true);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "";
  };
  WriteSmallRun(run, "small");
  WriteFile(run / kRunCompleteFile, "{\"files\": ");  // cut short
  WriteFile(run / "my_figure.png", "the user's\n");
  EXPECT_NE(refusal().find("holds an earlier run whose complete.json is not a completion record, "
                           "and also my_figure.png, which only that record could show to be the "
                           "run's; --force deletes only a run's own files"),
            std::string::npos);
  EXPECT_EQ(ReadTextFile(run / "my_figure.png"), "the user's\n");
  fs::remove(run / kRunCompleteFile);
  WriteFile(run / kRunCompleteFile / "config.yaml", "the user's\n");
  fs::remove(run / "my_figure.png");
  EXPECT_NE(refusal().find("holds an earlier run whose complete.json is a folder, not a completion "
                           "record"),
            std::string::npos);
  EXPECT_EQ(ReadTextFile(run / kRunCompleteFile / "config.yaml"), "the user's\n");
  // A record that lists a file outside the run's folder: the run is replaced, the file kept.
  fs::remove_all(run / kRunCompleteFile);
  WriteFile(dir / "x", "beside the run\n");
  WriteFile(run / kRunCompleteFile, "{\"files\": {\"../x\": 15, \"config.yaml\": 20}}\n");
  {
    StagedRunDirectory staged(run, true);
    WriteSmallRun(staged.staging(), "new");
    staged.Commit();
  }
  EXPECT_EQ(ReadTextFile(run / "config.yaml"), "name: new\nseed: 1\n");
  EXPECT_EQ(ReadTextFile(dir / "x"), "beside the run\n");
}

TEST(RunDirectoryTest, OtherFilesAreNeverDeletedEvenWithForce) {
  const fs::path dir = MakeTempDir("run_directory_foreign");
  WriteFile(dir / "thesis.tex", "\\documentclass{article}\n");
  // A config.yaml of some other tool is not a run either.
  WriteFile(dir / "other" / "config.yaml", "database: {host: localhost}\n");
  for (const fs::path& d : {dir, dir / "other"}) {
    SCOPED_TRACE(d.string());
    EXPECT_FALSE(HoldsPlywoodRun(d));
    EXPECT_THROW(StagedRunDirectory(d, true), ConfigError);
  }
  EXPECT_TRUE(fs::exists(dir / "thesis.tex"));
  EXPECT_TRUE(fs::exists(dir / "other" / "config.yaml"));
  // A file where the directory should be.
  EXPECT_THROW(StagedRunDirectory(dir / "thesis.tex", true), ConfigError);
  EXPECT_TRUE(fs::exists(dir / "thesis.tex"));
}

// A symbolic link given as the target is followed: the run lands in the folder it names (a rename
// onto the link itself failed after the whole run). A dangling link or a loop is named at once.
TEST(RunDirectoryTest, ASymbolicLinkTargetIsFollowedAndADanglingOneNamed) {
  const fs::path dir = MakeTempDir("run_directory_symlink");
  fs::create_directory(dir / "real");
  fs::create_directory_symlink(dir / "real", dir / "link");
  {
    StagedRunDirectory staged(dir / "link", false);
    WriteSmallRun(staged.staging(), "linked");
    staged.Commit();
  }
  EXPECT_TRUE(fs::is_symlink(dir / "link"));
  EXPECT_TRUE(fs::exists(dir / "real" / "config.yaml"));
  fs::create_directory_symlink(dir / "nowhere", dir / "dangling");
  fs::create_directory_symlink(dir / "loop_b", dir / "loop_a");
  fs::create_directory_symlink(dir / "loop_a", dir / "loop_b");
  for (const char* name : {"dangling", "loop_a"}) {
    try {
      StagedRunDirectory staged(dir / name, false);
      ADD_FAILURE() << name << " accepted";
    } catch (const ConfigError& e) {
      EXPECT_EQ(std::string(e.what()).rfind((dir / name).string() + ": is a symbolic link to ", 0),
                0u)
          << e.what();
    }
  }
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().string().find(".partial-"), std::string::npos) << entry.path();
  }
}

TEST(RunDirectoryTest, PartialOutputOfAKilledRunIsNamedAndThenCleanedUp) {
  const fs::path dir = MakeTempDir("run_directory_killed");
  // What `kill -9` leaves: the empty target and the staging folder of a process that is gone.
  fs::create_directories(dir / "run");
  const long gone = 999999999;  // above any pid_max
  WriteSmallRun(dir / ("run.partial-" + std::to_string(gone)), "small");
  const std::string why = WhyNotAFinishedRun(dir / "run");
  EXPECT_NE(why.find("no complete.json"), std::string::npos) << why;
  EXPECT_NE(why.find("run.partial-999999999 beside it is the partial output of a run that was "
                     "killed"),
            std::string::npos)
      << why;
  { StagedRunDirectory staged(dir / "run", false); }
  EXPECT_FALSE(fs::exists(dir / ("run.partial-" + std::to_string(gone))));
}

// The fixed file names of docs/run_outputs.md's table of files (the first cell of each row).
std::vector<std::string> DocumentedRunFileNames() {
  std::ifstream doc(testing::SourceRoot() / "docs" / "run_outputs.md");
  std::vector<std::string> names;
  bool in_table = false;
  for (std::string line; std::getline(doc, line);) {
    if (line.starts_with("| file | content |")) in_table = true;
    if (line.starts_with("## ")) in_table = false;
    if (!in_table || !line.starts_with("| `")) continue;
    const std::string cell = line.substr(0, line.find(" |", 2));
    for (std::size_t open = cell.find('`'); open != std::string::npos;) {
      const std::size_t close = cell.find('`', open + 1);
      if (close == std::string::npos) break;
      const std::string name = cell.substr(open + 1, close - open - 1);
      if (name.find('<') == std::string::npos) names.push_back(name);  // not trajectory.<name>.tum
      open = cell.find('`', close + 1);
    }
  }
  return names;
}

// s65 review: seed000_rooms' spot_round_objects.csv (stop 65) was missing from the names a run
// writes, so a run folder without its complete.json was refused by --force ("which no run
// writes") and a killed run's staging folder holding it was never cleaned up. Every file
// docs/run_outputs.md lists is a run's own.
TEST(RunDirectoryTest, EveryDocumentedOutputFileIsARunsOwn) {
  const std::vector<std::string> names = DocumentedRunFileNames();
  ASSERT_GE(names.size(), 20u) << "docs/run_outputs.md's table of files was not found";
  EXPECT_NE(std::find(names.begin(), names.end(), "spot_round_objects.csv"), names.end());
  const long gone = 999999999;  // above any pid_max
  for (const std::string& name : names) {
    // The two that make a folder a run, and the record, are tested above.
    if (name == "config.yaml" || name == "metrics.json" || name == "complete.json") continue;
    const fs::path dir = MakeTempDir("run_directory_documented_" + name);
    WriteSmallRun(dir / "run", "small");
    WriteFile(dir / "run" / name, "x\n");
    EXPECT_NO_THROW(StagedRunDirectory(dir / "run", true)) << name;
    const fs::path killed = dir / ("other.partial-" + std::to_string(gone));
    WriteSmallRun(killed, "small");
    WriteFile(killed / name, "x\n");
    { StagedRunDirectory staged(dir / "other", false); }
    EXPECT_FALSE(fs::exists(killed)) << name << ": a killed run's staging folder was kept";
  }
}

// s63 (forty-seventh pass): a symbolic link named like a killed run's staging folder
// (run.partial-PID, pointing at the user's own folder) was taken for one and deleted.
TEST(RunDirectoryTest, ALinkNamedLikeAStagingFolderIsLeftAlone) {
  const fs::path dir = MakeTempDir("run_directory_staging_link");
  WriteFile(dir / "user" / "pic.png", "the user's\n");
  fs::create_directory_symlink(dir / "user", dir / "run.partial-999999999");
  {
    StagedRunDirectory staged(dir / "run", false);
    WriteSmallRun(staged.staging(), "small");
    staged.Commit();
  }
  EXPECT_TRUE(fs::is_symlink(dir / "run.partial-999999999"));
  EXPECT_EQ(ReadTextFile(dir / "user" / "pic.png"), "the user's\n");
}

}  // namespace
}  // namespace plywood::sim
