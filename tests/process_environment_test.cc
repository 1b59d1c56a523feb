// The process environment a lab's machine or cluster gives plywood (docs/errors.md, the s65
// fifty-fourth pass): stack and memory limits, few file descriptors, standard streams closed, full
// or read by a pipe that closes early, a matplotlib that cannot write its cache. Each test sets the
// limit or stream in a child shell of its own and skips, saying why, where the machine cannot.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
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
using testing::PythonImports;
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

// True when user nobody (65534, through setpriv) can enter `dir`, run the built binary and read
// the tree's worlds and robots. A tree under /root (mode 0700 on a fresh Debian) is closed to every
// other user, and the tests that run plywood as nobody then skip, saying so, instead of failing
// with exit 126 (cannot execute).
bool NobodyCanRunPlywoodIn(const fs::path& dir) {
  const std::string command = "setpriv --reuid=65534 --regid=65534 --clear-groups sh -c 'cd \"" +
                              dir.string() + "\" && test -x \"" + PLYWOOD_BINARY_DIR +
                              "/apps/plywood\" && test -r \"" +
                              (SourceRoot() / "worlds/hall.xml").string() + "\" && test -r \"" +
                              (SourceRoot() / "models/p3dx.xml").string() + "\"' >/dev/null 2>&1";
  return std::system(command.c_str()) == 0;
}

constexpr const char* kNobodyCannotReach =
    "user nobody cannot reach the built binary or the tree (a folder above them is closed to "
    "other users, as /root is on a fresh Debian): clone the tree where others may enter to test "
    "this";

// Why plywood cannot be run here as user nobody with no other process of nobody's counting
// against a process limit ("" when it can): the process-limit tests need root and setpriv to
// become nobody, nobody idle, and `dir`, the binary and the tree within nobody's reach.
std::string WhyNotAloneAsNobody(const fs::path& dir) {
  if (geteuid() != 0 || std::system("setpriv --version >/dev/null 2>&1") != 0) {
    return "needs root and setpriv, to run as a user with no other processes";
  }
  if (std::system("pgrep -u nobody >/dev/null 2>&1") == 0) {
    return "nobody runs other processes, which count against the limit";
  }
  return NobodyCanRunPlywoodIn(dir) ? "" : kNobodyCannotReach;
}

// Runs plywood with `args` in `dir`, its stdout (and its stderr when `stderr_too`, else into
// dir/err) a pipe whose reader has already gone; its status as a shell gives it.
int RunIntoAPipeNobodyReads(const fs::path& dir, const std::vector<std::string>& args,
                            bool stderr_too) {
  int fds[2];
  if (pipe(fds) != 0) return -1;
  close(fds[0]);
  const std::string binary = std::string(PLYWOOD_BINARY_DIR) + "/apps/plywood";
  std::vector<std::string> words = {binary};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    if (chdir(dir.c_str()) != 0) _exit(126);
    dup2(fds[1], STDOUT_FILENO);
    const int err = stderr_too ? fds[1] : open("err", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(err, STDERR_FILENO);
    std::signal(SIGPIPE, SIG_DFL);  // as a shell starts a program
    execv(binary.c_str(), argv.data());
    _exit(127);
  }
  close(fds[1]);
  int status = 0;
  if (pid < 0 || waitpid(pid, &status, 0) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

bool CanSetInAShell(const std::string& limit) {
  return std::system(("bash -c '" + limit + "' 2>/dev/null").c_str()) == 0;
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

// A CARMEN log of `scans` FLASER lines of 181 beams seeing a flat wall 2 m ahead.
std::string FlatWallLog(int scans) {
  std::ostringstream log;
  for (int k = 0; k < scans; ++k) {
    log << "FLASER 181";
    for (int i = 0; i < 181; ++i) {
      const double c = std::cos((i - 90) * 3.141592653589793 / 180.0);
      log << " " << (c > 0.25 ? 2.0 / c : 8.0);
    }
    log << " 0 0 0 0 0 0 " << 0.1 * k << " host " << 0.1 * k << "\n";
  }
  return log.str();
}

// MuJoCo's mjVFS (2 MB of file-name slots) lay on the stack: under a stack limit below that every
// command that compiles a scene died of SIGSEGV, exit 139, without a line; a replay of a gzip log
// did under `ulimit -s 128` (the gzip reader's 64 kB line buffer and its end check's 128 kB).
TEST(ProcessEnvironmentTest, AStackLimitOfAQuarterMegabyteRuns) {
  if (!CanSetInAShell("ulimit -s 128")) GTEST_SKIP() << "this machine refuses ulimit -s 128";
  const fs::path dir = MakeTempDir("process_environment_stack");
  StillExperiment(dir, false);
  EXPECT_EQ(
      RunScript(dir, "ulimit -s 256\nexec \"$PLYWOOD\" run still.yaml --out out --quiet 2>err\n"),
      0)
      << Slurp(dir / "err");
  EXPECT_TRUE(fs::is_regular_file(dir / "out/metrics.json"));
  WriteFile(dir / "wall.log", FlatWallLog(5));
  EXPECT_EQ(RunScript(dir,
                      "gzip -f wall.log\nulimit -s 128\nexec \"$PLYWOOD\" replay wall.log.gz "
                      "--out replay >/dev/null 2>err\n"),
            0)
      << Slurp(dir / "err");
  EXPECT_TRUE(fs::is_regular_file(dir / "replay/metrics.json"));
}

// Below 128 kB Mesa's shader compiler overflowed the stack (bench, `--pictures` of the columns
// family), SIGSEGV without a line: such a limit is refused before anything runs.
TEST(ProcessEnvironmentTest, AStackLimitTooSmallForMesaIsRefusedOnOneLine) {
  if (!CanSetInAShell("ulimit -s 64")) GTEST_SKIP() << "this machine refuses ulimit -s 64";
  const fs::path dir = MakeTempDir("process_environment_small_stack");
  EXPECT_EQ(RunScript(dir,
                      "ulimit -s 64\nexec \"$PLYWOOD\" worlds generate columns --count 2 "
                      "--seed 2 --pictures --out w --quiet 2>err\n"),
            2);
  const std::string err = Slurp(dir / "err");
  EXPECT_EQ(Lines(err).size(), 1u) << err;
  EXPECT_EQ(
      err.rfind("plywood: ulimit -s: the stack limit is 64 kB; plywood needs at least 128 kB", 0),
      0u)
      << err;
  EXPECT_FALSE(fs::exists(dir / "w"));
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
    // The documented note of a snapshot drawn in software may come first; the error is one line.
    std::vector<std::string> lines = Lines(Slurp(dir / "err"));
    std::erase_if(lines, [](const std::string& line) {
      return line.starts_with("plywood: offscreen OpenGL rendering unavailable");
    });
    const std::string err = lines.empty() ? "" : lines.front();
    if (status == 127 && err.find("error while loading shared libraries") != std::string::npos) {
      continue;  // too small for the program to start: the dynamic loader's line, not ours
    }
    if (status == 0) continue;
    ++refused;
    EXPECT_EQ(status, 1) << kb << " kB: " << err;
    EXPECT_EQ(lines.size(), 1u) << kb << " kB: " << Slurp(dir / "err");
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

// Under a limit of some hundred MB, where the run's own memory is plenty: the GL library's preload
// thread beside the scene's compile (stop 67) made this run end in std::bad_alloc (exit 1, each of
// three at 500 MB), and others abort in llvmpipe's JIT or hang (review68).
TEST(ProcessEnvironmentTest, ARunUnderAMemoryLimitOfHundredsOfMegabytesRuns) {
  if (!CanSetInAShell("ulimit -v 500000")) GTEST_SKIP() << "this machine refuses ulimit -v";
  const fs::path dir = MakeTempDir("process_environment_roomy_memory");
  StillExperiment(dir, true);
  for (int run = 0; run < 2; ++run) {
    fs::remove_all(dir / "out");
    // Killed after a minute: a hung run is a failure, not a stuck test.
    const int status = RunScript(dir,
                                 "ulimit -v 500000\nexec timeout -s KILL 60 \"$PLYWOOD\" run "
                                 "still.yaml --out out --quiet 2>err\n");
    EXPECT_EQ(status, 0) << Slurp(dir / "err");
    EXPECT_TRUE(fs::exists(dir / "out" / "snapshot.png")) << Slurp(dir / "err");
  }
}

// A training set larger than the memory limit allows: std::bad_alloc was "plywood: error:
// std::bad_alloc", naming neither memory nor the limit.
TEST(ProcessEnvironmentTest, AnAllocationPastTheMemoryLimitSaysOutOfMemory) {
  if (!CanSetInAShell("ulimit -v 70000")) GTEST_SKIP() << "this machine refuses ulimit -v";
  const fs::path dir = MakeTempDir("process_environment_bad_alloc");
  const int status =
      RunScript(dir,
                "ulimit -v 70000\nexec \"$PLYWOOD\" train sonar-net --rooms 1 "
                "--test-rooms 1 --poses 50000 --epochs 1 --out w.txt --quiet 2>err\n");
  const std::string err = Slurp(dir / "err");
  EXPECT_EQ(status, 1) << err;
  EXPECT_EQ(Lines(err).size(), 1u) << err;
  EXPECT_EQ(err.rfind("plywood: error: out of memory", 0), 0u) << err;
  EXPECT_NE(err.find("(the memory limit, ulimit -v, is 70000 kB)"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir / "w.txt"));
}

// `plywood sweep ... 2>&1 | head -1`: the next progress line met a closed pipe and SIGPIPE killed
// the sweep, its running runs with it (they die with the sweep), and no results.csv. Now every run
// finishes and is recorded; plywood then dies of SIGPIPE, as a program whose reader left does, once
// its files are written. (The pipe's reader is gone before plywood starts, so no run of the test
// depends on when `head` would have exited.)
TEST(ProcessEnvironmentTest, ASweepWhoseReaderLeavesFinishesAndRecordsEveryRun) {
  const fs::path dir = MakeTempDir("process_environment_pipe");
  ThreeRunSweep(dir);
  const int status = RunIntoAPipeNobodyReads(dir, {"sweep", "three.yaml", "--out", "out"}, true);
  EXPECT_EQ(status, 128 + SIGPIPE);
  EXPECT_EQ(DataLines(dir / "out/results.csv"), 3) << Slurp(dir / "out/results.csv");
}

// The plot script printed each plot's name into the closed pipe (`plywood sweep ... | true`): a
// BrokenPipeError traceback, the plots after the first unmade, and "plotting failed (see above)".
TEST(ProcessEnvironmentTest, APlotScriptWhoseReaderLeftPrintsNoTraceback) {
  if (!PythonImports("matplotlib")) GTEST_SKIP() << "python3-matplotlib is not installed";
  const fs::path dir = MakeTempDir("process_environment_plot_pipe");
  ThreeRunSweep(dir);
  EXPECT_EQ(RunIntoAPipeNobodyReads(dir, {"sweep", "three.yaml", "--out", "out"}, false),
            128 + SIGPIPE);
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
  if (!PythonImports("matplotlib")) GTEST_SKIP() << "python3-matplotlib is not installed";
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
  if (!PythonImports("matplotlib")) GTEST_SKIP() << "python3-matplotlib is not installed";
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

// GALLIUM_DRIVER=softpipe drew another snapshot.png than the same seed's without a word;
// swrast, or a name Mesa does not know, crashed it (SIGSEGV, exit 139). llvmpipe, the default,
// gives the same bytes as no variable.
TEST(ProcessEnvironmentTest, AMesaDriverThatDrawsOtherPixelsIsRefused) {
  const fs::path dir = MakeTempDir("process_environment_gallium");
  StillExperiment(dir, true);
  for (const std::string driver : {"softpipe", "swrast"}) {
    fs::remove_all(dir / "out");
    EXPECT_EQ(RunScript(dir, "GALLIUM_DRIVER=" + driver +
                                 " \"$PLYWOOD\" run still.yaml --out out --quiet 2>err\n"),
              2)
        << driver;
    const std::string err = Slurp(dir / "err");
    EXPECT_EQ(Lines(err).size(), 1u) << err;
    EXPECT_EQ(err.rfind("plywood: GALLIUM_DRIVER: " + driver + ": ", 0), 0u) << err;
    EXPECT_FALSE(fs::exists(dir / "out"));
  }
  ASSERT_EQ(
      RunScript(dir,
                "set -e\n\"$PLYWOOD\" run still.yaml --out plain --quiet\n"
                "GALLIUM_DRIVER=llvmpipe \"$PLYWOOD\" run still.yaml --out llvmpipe --quiet\n"),
      0);
  EXPECT_EQ(Slurp(dir / "plain/snapshot.png"), Slurp(dir / "llvmpipe/snapshot.png"));
}

// `umask 0777` as a user other than root: every folder plywood made was one it could not enter, so
// a run failed writing config.yaml and left OUT and OUT.partial-PID, mode 000, behind (`train` its
// scratch folder in TMPDIR). Root is not stopped by modes, so the test runs as nobody when it is
// root, and as itself otherwise.
TEST(ProcessEnvironmentTest, AUmaskThatDeniesTheOwnerIsRefusedAndLeavesNothing) {
  std::string as_another_user;
  if (geteuid() == 0) {
    if (std::system("setpriv --version >/dev/null 2>&1") != 0) {
      GTEST_SKIP() << "runs as root without setpriv to become another user";
    }
    as_another_user = "setpriv --reuid=65534 --regid=65534 --clear-groups ";
  }
  const fs::path dir = MakeTempDir("process_environment_umask");
  fs::permissions(dir, fs::perms::all);
  if (!as_another_user.empty() && !NobodyCanRunPlywoodIn(dir)) GTEST_SKIP() << kNobodyCannotReach;
  StillExperiment(dir, false);
  fs::permissions(dir / "still.yaml", fs::perms::all);
  EXPECT_EQ(RunScript(dir, as_another_user +
                               "bash -c 'umask 0777; exec \"$PLYWOOD\" run still.yaml --out out "
                               "--quiet 2>err'\n"),
            2);
  const std::string err = Slurp(dir / "err");
  fs::permissions(dir / "err", fs::perms::all);
  EXPECT_EQ(Lines(err).size(), 1u) << err;
  EXPECT_EQ(err.rfind("plywood: umask 0777: ", 0), 0u) << err;
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().filename().string().rfind("out", 0), std::string::npos)
        << entry.path() << " was left";
  }
}

// Under `ulimit -u 3` Mesa's llvmpipe could not start its rasteriser threads and waited for them
// forever: the run hung in its snapshot. The limit counts every process and thread of the user, so
// the test runs as nobody (through setpriv, as root) and only while nobody runs nothing else.
TEST(ProcessEnvironmentTest, AProcessLimitNeverHangsTheSnapshot) {
  const fs::path dir = MakeTempDir("process_environment_nproc");
  fs::permissions(dir, fs::perms::all);
  if (const std::string why = WhyNotAloneAsNobody(dir); !why.empty()) GTEST_SKIP() << why;
  StillExperiment(dir, true);
  const int status = RunScript(
      dir,
      "timeout 20 setpriv --reuid=65534 --regid=65534 --clear-groups bash -c 'ulimit -u 3; exec "
      "\"$PLYWOOD\" run still.yaml --out out --quiet 2>err'\n");
  const std::string err = Slurp(dir / "err");
  EXPECT_NE(status, 124) << "timed out: the run hung";
  if (status != 0) {  // else the snapshot was drawn
    EXPECT_EQ(Lines(err).size(), 1u) << err;
    EXPECT_NE(err.find("(the process limit, ulimit -u, is 3)"), std::string::npos) << err;
  }
}

// `sweep --jobs 4` under a process limit that lets two runs start: the third fork failed and the
// sweep ended, "plywood: error: cannot start a run: fork failed", exit 1, its two runs killed with
// it. Now a cell waits for a run to end, so the sweep runs as many at once as the limit allows.
TEST(ProcessEnvironmentTest, ASweepUnderAProcessLimitRunsAsManyAtOnceAsItAllows) {
  const fs::path dir = MakeTempDir("process_environment_nproc_sweep");
  fs::permissions(dir, fs::perms::all);
  if (const std::string why = WhyNotAloneAsNobody(dir); !why.empty()) GTEST_SKIP() << why;
  ThreeRunSweep(dir);
  const int status = RunScript(
      dir,
      "timeout 60 setpriv --reuid=65534 --regid=65534 --clear-groups bash -c 'ulimit -u 3; exec "
      "\"$PLYWOOD\" sweep three.yaml --jobs 4 --out out --no-collect --quiet 2>err'\n");
  EXPECT_EQ(status, 0) << Slurp(dir / "err");
  int finished = 0;
  for (const auto& run : fs::directory_iterator(dir / "out/runs")) {
    finished += fs::is_regular_file(run.path() / "complete.json") ? 1 : 0;
  }
  EXPECT_EQ(finished, 3);
}

}  // namespace
}  // namespace plywood
