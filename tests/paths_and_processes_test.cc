// Processes side by side on one folder and paths of every kind (docs/errors.md, the s64
// fifty-second pass): a collect beside a running sweep, the modes of the files a sweep shares, an
// experiment or sweep reached through a symbolic link, a file whose name starts with '-'.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "plywood_paths.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing::MakeTempDir;
using testing::RunPlywood;
using testing::Slurp;
using testing::SourceRoot;
using testing::WriteFile;

// One second of a robot standing still in the hall: the cheapest run there is.
std::string StillExperiment(const std::string& world) {
  return "name: still\nseed: 1\nduration_s: 1\nworld: " + world +
         "\nrobot: {model: p3dx}\ncontroller: {type: idle}\noutput: {snapshot: false}\n";
}

// A sweep of that run, one cell.
fs::path OneCellSweep(const fs::path& dir) {
  WriteFile(dir / "still.yaml", StillExperiment((SourceRoot() / "worlds/hall.xml").string()));
  return WriteFile(dir / "one.yaml", "experiment: still.yaml\nseeds: [1]\n");
}

void ExpectOneLineNaming(const CliResult& result, const std::string& what, const std::string& why) {
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_EQ(result.err.find('\n'), result.err.size() - 1) << "not one line: " << result.err;
  EXPECT_EQ(result.err.rfind("plywood: " + what + ": ", 0), 0u) << result.err;
  EXPECT_NE(result.err.find(why), std::string::npos) << result.err;
}

// A flock held by the test, as the process that holds it in use would.
class HeldLock {
 public:
  HeldLock(const fs::path& file, int how) : fd_(open(file.c_str(), O_RDONLY | O_CLOEXEC)) {
    ok_ = fd_ >= 0 && flock(fd_, how | LOCK_NB) == 0;
  }
  ~HeldLock() {
    if (fd_ >= 0) close(fd_);
  }
  HeldLock(const HeldLock&) = delete;
  HeldLock& operator=(const HeldLock&) = delete;
  bool ok() const { return ok_; }

 private:
  int fd_;
  bool ok_ = false;
};

// `sweep --collect` took no lock: beside a running sweep (or another collect) it rewrote the
// tables the sweep was writing, leaving one's results.csv beside the other's summary.csv, and
// exited as if it had collected a finished sweep.
TEST(PathsAndProcessesTest, ACollectBesideARunningSweepOrAnotherCollectIsRefused) {
  const fs::path dir = MakeTempDir("CollectBesideASweep");
  const fs::path out = dir / "out";
  const CliResult sweep = RunPlywood(
      "sweep " + OneCellSweep(dir).string() + " --quiet --no-collect --out " + out.string(), dir);
  ASSERT_EQ(sweep.exit_code, 0) << sweep.err;
  ASSERT_FALSE(fs::exists(out / "summary.csv"));
  const std::string collect = "sweep --collect " + out.string() + " --quiet";
  {
    const HeldLock running_sweep(out / "sweep.lock", LOCK_EX);
    ASSERT_TRUE(running_sweep.ok());
    ExpectOneLineNaming(RunPlywood(collect, dir), out.string(),
                        "a plywood sweep is running in this folder");
    EXPECT_FALSE(fs::exists(out / "summary.csv"));  // nothing written
  }
  {
    const HeldLock other_collect(out, LOCK_EX);
    ASSERT_TRUE(other_collect.ok());
    ExpectOneLineNaming(RunPlywood(collect, dir), out.string(),
                        "another plywood sweep --collect is writing this folder's tables");
    EXPECT_FALSE(fs::exists(out / "summary.csv"));
  }
  {
    // A sweep beside a collect (sweep.lock shared, the folder locked) names the collect, not a
    // sweep that is not running.
    const HeldLock collect_on_lock(out / "sweep.lock", LOCK_SH), collect_on_folder(out, LOCK_EX);
    ASSERT_TRUE(collect_on_lock.ok() && collect_on_folder.ok());
    ExpectOneLineNaming(
        RunPlywood("sweep " + (dir / "one.yaml").string() + " --quiet --out " + out.string(), dir),
        out.string(), "a plywood sweep --collect is writing this folder's tables; wait for it");
  }
  // A shard of a Slurm array holds sweep.lock shared and writes no table: a collect runs beside it.
  const HeldLock shard(out / "sweep.lock", LOCK_SH);
  ASSERT_TRUE(shard.ok());
  const CliResult beside_a_shard = RunPlywood(collect, dir);
  EXPECT_EQ(beside_a_shard.exit_code, 0) << beside_a_shard.err;
  EXPECT_TRUE(fs::exists(out / "summary.csv"));
}

// Under umask 002 (a group sharing a sweep folder) every file a sweep writes was group-writable
// but sweep.lock and the runs' logs, made 0644: a teammate's sweep could not open the lock for
// writing and ran unlocked without a word.
TEST(PathsAndProcessesTest, FilesASweepSharesTakeTheUmasksModeAsTheRestDo) {
  const fs::path dir = MakeTempDir("SweepUmask");
  const fs::path out = dir / "out";
  const fs::path sweep = OneCellSweep(dir);
  const mode_t old_mask = umask(002);
  const CliResult result =
      RunPlywood("sweep " + sweep.string() + " --quiet --out " + out.string(), dir);
  umask(old_mask);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto mode = [](const fs::path& file) {
    return static_cast<unsigned>(fs::status(file).permissions() & fs::perms::mask);
  };
  EXPECT_EQ(mode(out / "results.csv"), 0664u);
  EXPECT_EQ(mode(out / "sweep.lock"), 0664u);
  int logs = 0;
  for (const auto& log : fs::directory_iterator(out / "logs")) {
    EXPECT_EQ(mode(log.path()), 0664u) << log.path();
    ++logs;
  }
  EXPECT_EQ(logs, 1);
}

// An experiment (or a sweep) reached through a symbolic link resolved its relative paths beside
// the link: the world beside the file it names was "no such file", and a world of that name beside
// the link was run instead. The file's own folder is what its author wrote the paths against
// (docs/experiments.md): the same file gives the same run by whichever name it is given.
TEST(PathsAndProcessesTest, AFileGivenThroughALinkResolvesItsPathsBesideTheFileItNames) {
  const fs::path dir = MakeTempDir("ExperimentThroughALink");
  const fs::path lab = dir / "lab", mine = dir / "mine";
  fs::copy_file(SourceRoot() / "worlds/hall.xml", WriteFile(lab / "room.xml", ""),
                fs::copy_options::overwrite_existing);
  WriteFile(lab / "still.yaml", StillExperiment("room.xml"));
  WriteFile(lab / "one.yaml", "experiment: still.yaml\nseeds: [1]\n");
  fs::create_directories(mine);
  fs::create_symlink("../lab/still.yaml", mine / "mine.yaml");
  fs::create_symlink(fs::absolute(lab / "one.yaml"), mine / "sweep.yaml");

  const CliResult run = RunPlywood(
      "run " + (mine / "mine.yaml").string() + " --quiet --out " + (dir / "run").string(), dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(Slurp(dir / "run/config.yaml").find("world: " + (lab / "room.xml").string() + "\n"),
            std::string::npos)
      << Slurp(dir / "run/config.yaml");

  // A world of the name beside the link is not the one the file means.
  WriteFile(mine / "room.xml", "<mujoco/>\n");
  const CliResult sweep = RunPlywood(
      "sweep " + (mine / "sweep.yaml").string() + " --quiet --out " + (dir / "sweep").string(),
      dir);
  ASSERT_EQ(sweep.exit_code, 0) << sweep.err;
  EXPECT_NE(Slurp(dir / "sweep/results.csv").find(",room.xml,"), std::string::npos)
      << Slurp(dir / "sweep/results.csv");
}

// `--`, which ends the flags, was refused as "unknown option --": a file whose name starts with
// '-' could be given only as ./-e.yaml.
TEST(PathsAndProcessesTest, ADoubleDashEndsTheFlagsSoAFileMayStartWithADash) {
  const fs::path dir = MakeTempDir("DoubleDash");
  WriteFile(dir / "-e.yaml", StillExperiment((SourceRoot() / "worlds/hall.xml").string()));
  const CliResult run = RunPlywood("run --quiet --out out -- -e.yaml", dir, dir);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::exists(dir / "out/metrics.json"));
  // Without it the name is still taken for a flag, and named.
  const CliResult flag = RunPlywood("run --quiet --out out2 -e.yaml", dir, dir);
  EXPECT_EQ(flag.exit_code, 2);
  EXPECT_EQ(flag.err, "plywood: run: unknown option -e.yaml (see plywood run --help)\n");
}

// A relative path given in a current folder deleted since the shell entered it read "../e.yaml:
// No such file or directory", the file there all along: the line now says why.
TEST(PathsAndProcessesTest, ARelativePathInADeletedCurrentFolderSaysTheFolderIsGone) {
  const fs::path dir = MakeTempDir("DeletedCurrentFolder");
  WriteFile(dir / "still.yaml", StillExperiment((SourceRoot() / "worlds/hall.xml").string()));
  fs::create_directories(dir / "gone");
  const std::string command = "cd '" + (dir / "gone").string() + "' && rmdir ../gone && " +
                              (fs::path(PLYWOOD_BINARY_DIR) / "apps" / "plywood").string() +
                              " run ../still.yaml --quiet --out '" + (dir / "out").string() +
                              "' 2>'" + (dir / "stderr").string() + "'";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_EQ(Slurp(dir / "stderr"),
            "plywood: ../still.yaml: No such file or directory (the current folder was deleted, so "
            "no relative path can be found in it: cd to a folder that exists)\n");
  EXPECT_FALSE(fs::exists(dir / "out"));
  // An absolute path is not looked for in the current folder: its being gone is not named as why.
  const std::string absolute = "cd '" + dir.string() + "' && mkdir gone2 && cd gone2 && rmdir " +
                               "../gone2 && " +
                               (fs::path(PLYWOOD_BINARY_DIR) / "apps" / "plywood").string() +
                               " run '" + (dir / "missing.yaml").string() + "' --quiet --out '" +
                               (dir / "out").string() + "' 2>'" + (dir / "stderr").string() + "'";
  const int absolute_status = std::system(absolute.c_str());
  ASSERT_TRUE(WIFEXITED(absolute_status));
  EXPECT_EQ(WEXITSTATUS(absolute_status), 2);
  EXPECT_EQ(Slurp(dir / "stderr"),
            "plywood: " + (dir / "missing.yaml").string() + ": no such experiment file\n");
}

// An --out that is a symbolic link to nowhere read "cannot create the sweep folder: File exists"
// (sweep; worlds generate alike; train for the folder of its --out), naming neither the link nor
// where it points; `run` already said so.
TEST(PathsAndProcessesTest, AnOutThatLinksToNowhereIsNamedAsSuch) {
  const fs::path dir = MakeTempDir("OutLinksToNowhere");
  const fs::path link = dir / "results";
  fs::create_symlink(dir / "missing", link);
  const std::string nowhere = link.string() + ": is a symbolic link to " +
                              (dir / "missing").string() +
                              ", which does not exist (or links round in a loop)";
  const CliResult sweep =
      RunPlywood("sweep " + OneCellSweep(dir).string() + " --quiet --out " + link.string(), dir);
  EXPECT_EQ(sweep.exit_code, 2);
  EXPECT_EQ(sweep.err, "plywood: " + nowhere + "; make that folder or choose another --out\n");
  const CliResult generate =
      RunPlywood("worlds generate room --count 1 --seed 1 --quiet --out " + link.string(), dir);
  EXPECT_EQ(generate.exit_code, 2);
  EXPECT_EQ(generate.err, "plywood: worlds generate: --out: " + nowhere +
                              "; make that folder or choose another folder\n");
  const CliResult train =
      RunPlywood("train sonar-net --rooms 2 --test-rooms 1 --poses 3 --epochs 1 --quiet --out " +
                     (link / "net.txt").string(),
                 dir);
  EXPECT_EQ(train.exit_code, 2);
  EXPECT_EQ(train.err, "plywood: train: --out: " + (link / "net.txt").string() + ": its folder " +
                           link.string() + " is a symbolic link to " + (dir / "missing").string() +
                           ", which does not exist (or links round in a loop)\n");
  EXPECT_FALSE(fs::exists(dir / "missing"));
}

// A file name of 250 bytes (the file system takes 255) was refused, "NAME: cannot write: File name
// too long" (train --out, score --out, any staged write): its staged copy NAME.partial-PID was the
// name too long.
TEST(PathsAndProcessesTest, AFileNameNearTheFileSystemsLimitIsWritten) {
  const fs::path dir = MakeTempDir("NameNearNameMax");
  const fs::path out = dir / (std::string(246, 'n') + ".txt");
  const CliResult train = RunPlywood(
      "train sonar-net --rooms 2 --test-rooms 1 --poses 3 --epochs 1 --quiet --out " + out.string(),
      dir);
  EXPECT_EQ(train.exit_code, 0) << train.err;
  EXPECT_TRUE(Slurp(out).starts_with("plywood-sonar-net 1\n"));
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) files += entry.is_regular_file();
  EXPECT_EQ(files, 3);  // the weights, stdout and stderr: no staged copy left
}

// Two generations at once into one folder (another seed or count) both exited 0, the worlds of
// the one that finished first left unlisted beside the other's index.csv. Here the generation
// beside is the test, holding the folder's lock.
TEST(PathsAndProcessesTest, AGenerationBesideAnotherInOneFolderIsRefused) {
  const fs::path dir = MakeTempDir("GenerationsIntoOneOut");
  const fs::path out = dir / "worlds";
  fs::create_directories(out);
  const std::string generate =
      "worlds generate room --count 2 --seed 2 --quiet --out " + out.string();
  {
    const HeldLock other_generation(out, LOCK_EX);
    ASSERT_TRUE(other_generation.ok());
    const CliResult beside = RunPlywood(generate, dir);
    EXPECT_EQ(beside.exit_code, 2) << beside.err;
    EXPECT_EQ(beside.err, "plywood: worlds generate: --out: " + out.string() +
                              ": another plywood worlds generate is writing this folder; wait for "
                              "it or choose another folder\n");
    EXPECT_TRUE(fs::is_empty(out));
  }
  const CliResult after = RunPlywood(generate, dir);
  EXPECT_EQ(after.exit_code, 0) << after.err;
  EXPECT_TRUE(fs::exists(out / "index.csv"));
}

// Two trainings into one --out both exited 0, each saying "weights written to" it, while the file
// held the weights of the one that finished last. Here the other process is the test, writing the
// file once the training has drawn its rooms. The write must land while the epochs run: 120 of
// them take some 0.8 s here (40 took 0.3 s), the margin for a faster or busier host.
TEST(PathsAndProcessesTest, WeightsSomeoneElseWroteWhileTrainingAreNotReplaced) {
  const fs::path dir = MakeTempDir("TrainingsIntoOneOut");
  const fs::path out = dir / "net.txt";
  const std::string command =
      (fs::path(PLYWOOD_BINARY_DIR) / "apps" / "plywood").string() +
      " train sonar-net --rooms 4 --test-rooms 1 --poses 10 --epochs 120 --out " + out.string() +
      " 2>" + (dir / "stderr").string();
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  char line[512];
  bool data_drawn = false;
  while (!data_drawn && std::fgets(line, sizeof line, pipe) != nullptr) {
    data_drawn = std::string(line).starts_with("data: ");
  }
  EXPECT_TRUE(data_drawn);
  WriteFile(out, "another training's weights\n");
  while (std::fgets(line, sizeof line, pipe) != nullptr) {
  }
  const int status = pclose(pipe);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  const std::string err = Slurp(dir / "stderr");
  EXPECT_EQ(err.find('\n'), err.size() - 1) << "not one line: " << err;
  EXPECT_EQ(
      err.rfind("plywood: train: --out: " + out.string() +
                    ": another process wrote it while this one trained; these weights are in " +
                    out.string() + ".partial-",
                0),
      0u)
      << err;
  EXPECT_EQ(Slurp(out), "another training's weights\n");
  int kept = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().filename().string().starts_with("net.txt.partial-")) {
      EXPECT_TRUE(Slurp(entry.path()).starts_with("plywood-sonar-net 1\n"));
      ++kept;
    }
  }
  EXPECT_EQ(kept, 1);
}

}  // namespace
}  // namespace plywood
