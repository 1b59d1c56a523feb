// `plywood view` as a user runs it, under Xvfb (started by the test; the program exits 77, a
// visible skip, without it).

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "plywood_paths.h"
#include "render/png_image.h"
#include "sim/runner/run_directory.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"
#include "tests/support/xvfb_display.h"
#include "viewer/view_controls.h"

namespace plywood {
namespace {

using testing::MakeTempDir;
using testing::RunPlywood;
using testing::Slurp;
using testing::SourceRoot;

// Whether the X server on `display` shows a window: one of the root's children is mapped
// (xwininfo, Debian's x11-utils). GLFW maps its window only once the GL context exists; killed
// before, Mesa's GLX can crash inside glfwCreateWindow (docs/errors.md, sixth pass).
bool DisplayShowsAWindow(int display) {
  const std::string on = " -display :" + std::to_string(display);
  const std::string command = "for w in $(xwininfo -root -children" + on +
                              " 2>/dev/null | awk '/^ +0x/{print $1}'); do xwininfo -id $w" + on +
                              " 2>/dev/null; done";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return false;
  std::string text;
  char buffer[256];
  while (std::fgets(buffer, sizeof(buffer), pipe) != nullptr) text += buffer;
  pclose(pipe);
  return text.find("IsViewable") != std::string::npos;
}

// s50 (re-check of issue 11, "plywood <cmd> --help lists every flag"): tests/cli_help_test.cc
// checks every command but `view`, which only a viewer build has. No display needed.
TEST(ViewHelpTest, HelpListsEveryFlagAndAnUnknownOneIsNamed) {
  const std::filesystem::path dir = MakeTempDir("view_help");
  for (const char* help : {"--help", "-h"}) {
    const auto r = RunPlywood(std::string("view ") + help, dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    for (const char* flag : {"TARGET", "--out", "--seed", "--set", "--force", "--speed", "--paused",
                             "--exit-at-end", "--screenshot", "--time", "--size", "--no-panel",
                             "--quiet", "--bench", "--bench-seconds", "--help"}) {
      EXPECT_NE(r.out.find(flag), std::string::npos) << flag << " missing from:\n" << r.out;
    }
    EXPECT_NE(r.out.find("Example"), std::string::npos) << r.out;
  }
  const auto unknown = RunPlywood("view --colour", dir);
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_EQ(unknown.err, "plywood: view: unknown option --colour (see plywood view --help)\n");
}

// Splits `text` into its runs of letters and digits.
std::vector<std::string> Words(const std::string& text) {
  std::vector<std::string> words;
  std::string word;
  for (const char c : text + ' ') {
    if (std::isalnum(static_cast<unsigned char>(c)) != 0) {
      word += c;
    } else if (!word.empty()) {
      words.push_back(std::exchange(word, {}));
    }
  }
  return words;
}

// s62: the footer of `view --help` left out G (seed 001's occupancy grid), which the window's own
// F1 help lists. Every key of that help (the text before each tab) is a word of the footer.
TEST(ViewHelpTest, HelpNamesEveryKeyTheWindowsF1HelpLists) {
  const std::filesystem::path dir = MakeTempDir("view_help_keys");
  const auto r = RunPlywood("view --help", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string footer = r.out.substr(r.out.find("Keys:"));
  std::vector<std::string> footer_words;
  for (std::string word : Words(footer)) {
    std::transform(word.begin(), word.end(), word.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    footer_words.push_back(word);
  }
  const std::string help = viewer::ViewControls::HelpText();
  std::size_t line_start = 0;
  while (line_start < help.size()) {
    const std::size_t line_end = std::min(help.find('\n', line_start), help.size());
    const std::string line = help.substr(line_start, line_end - line_start);
    for (std::string key : Words(line.substr(0, line.find('\t')))) {
      std::transform(key.begin(), key.end(), key.begin(),
                     [](unsigned char c) { return std::tolower(c); });
      EXPECT_NE(std::find(footer_words.begin(), footer_words.end(), key), footer_words.end())
          << "key '" << key << "' (F1 help: " << line << ") missing from:\n"
          << footer;
    }
    line_start = line_end + 1;
  }
}

class ViewCliTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { testing::RequireXvfbOrSkip(); }
};

// A finished one-second run of the default experiment in dir/run (no snapshot), for the tests
// that view or refuse a run directory.
std::filesystem::path OneSecondRun(const std::filesystem::path& dir) {
  const std::filesystem::path run = dir / "run";
  const testing::CliResult result =
      RunPlywood("run " + (SourceRoot() / "experiments/default.yaml").string() +
                     " --set duration_s=1 --quiet --no-snapshot --out " + run.string(),
                 dir);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  return run;
}

TEST_F(ViewCliTest, AnUntouchedViewedRunWritesTheSameBytesAsPlywoodRun) {
  const std::filesystem::path dir = MakeTempDir("view_cli_identity");
  const std::string experiment = (SourceRoot() / "experiments/default.yaml").string();
  const std::string common = experiment + " --seed 3 --set duration_s=6 --quiet";
  const testing::CliResult viewed =
      RunPlywood("view " + common + " --speed max --exit-at-end --size 320x240 --out " +
                     (dir / "viewed").string(),
                 dir);
  ASSERT_EQ(viewed.exit_code, 0) << viewed.err;
  const testing::CliResult run =
      RunPlywood("run " + common + " --out " + (dir / "run").string(), dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* file :
       {"metrics.json", "trajectory.csv", "laser.log", "sonar.csv", "config.yaml"}) {
    const std::string expected = Slurp(dir / "run" / file);
    EXPECT_FALSE(expected.empty()) << file;
    EXPECT_EQ(Slurp(dir / "viewed" / file), expected) << file;
  }
}

// The command that made docs/viewer.png (README): the office after 20 s, every overlay on.
TEST_F(ViewCliTest, ScreenshotCommandOfTheReadme) {
  const std::filesystem::path dir = MakeTempDir("view_cli_screenshot");
  const testing::CliResult result =
      RunPlywood("view " + (SourceRoot() / "experiments/default.yaml").string() +
                     " --set duration_s=20 --speed max --size 960x600 --quiet --out " +
                     (dir / "run").string() + " --screenshot " + (dir / "viewer.png").string(),
                 dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const render::RgbImage picture = render::ReadPng(dir / "viewer.png");
  EXPECT_EQ(picture.width, 960);
  EXPECT_EQ(picture.height, 600);
  EXPECT_FALSE(Slurp(dir / "run" / "metrics.json").empty());
}

TEST_F(ViewCliTest, RefusesARunDirectoryThatDidNotFinishInOneLine) {
  const std::filesystem::path dir = MakeTempDir("view_cli_refusal");
  const std::filesystem::path run = OneSecondRun(dir);
  ASSERT_FALSE(::testing::Test::HasFailure());
  std::filesystem::remove(run / "metrics.json");
  const testing::CliResult result = RunPlywood("view " + run.string() + " --screenshot x.png", dir);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("metrics.json"), std::string::npos) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
}

// s63: the replay drew whatever sonar.csv held: a range of -5 as a beam pointing backwards, 1e300
// as one across the screen, a 17th column as a transducer at the robot's centre; and laser.log's
// scans out of time order showed another moment's scan, exit 0 (the files' sizes in complete.json
// were the only guard, and an edit of the same length passes it). A range outside [range_min_m,
// range_max_m] of config.yaml's sonar, columns other than the ring's, or a scan before the one
// above it is refused in one line naming the file, its line and the field.
TEST_F(ViewCliTest, SensorFilesNoRunCouldHaveWrittenAreRefusedNamingTheirField) {
  const std::filesystem::path dir = MakeTempDir("view_cli_sensor_files");
  const std::filesystem::path run = OneSecondRun(dir);
  ASSERT_FALSE(::testing::Test::HasFailure());
  const auto lines_of = [](const std::string& text) {
    std::vector<std::string> lines;
    for (std::size_t at = 0; at < text.size();) {
      const std::size_t end = text.find('\n', at);
      lines.push_back(text.substr(at, end - at));
      at = end + 1;
    }
    return lines;
  };
  // A copy of the run whose `file` has its lines changed by `edit`, complete.json rewritten.
  const auto copy_with = [&](const std::string& name, const std::string& file, const auto& edit) {
    const std::filesystem::path copy = dir / name;
    std::filesystem::copy(run, copy, std::filesystem::copy_options::recursive);
    std::vector<std::string> changed = lines_of(Slurp(run / file));
    EXPECT_GT(changed.size(), 8u);
    edit(changed);
    std::string text;
    for (const std::string& line : changed) text += line + "\n";
    testing::WriteFile(copy / file, text);
    sim::WriteCompletionRecord(copy);
    return copy;
  };
  // Line 3 of the file (its second ring) with its first range set to `range`.
  const auto first_range = [&](const std::string& range) {
    return [range](std::vector<std::string>& changed) {
      std::string& line = changed[2];
      const std::size_t first = line.find(',') + 1;
      line = line.substr(0, first) + range + line.substr(line.find(',', first));
    };
  };
  const std::filesystem::path negative = copy_with("negative", "sonar.csv", first_range("-5"));
  const std::filesystem::path far = copy_with("far", "sonar.csv", first_range("1e300"));
  const std::filesystem::path at_max = copy_with("at_max", "sonar.csv", first_range("5"));
  const std::filesystem::path wide =
      copy_with("wide", "sonar.csv", [](std::vector<std::string>& changed) {
        changed[0] += ",range_16_m";
        for (std::size_t i = 1; i < changed.size(); ++i) changed[i] += ",1";
      });
  // laser.log: two comment lines, two PARAM lines, then one scan a line from t = 0 every 0.1 s.
  const std::filesystem::path unordered =
      copy_with("unordered", "laser.log", [](std::vector<std::string>& changed) {
        EXPECT_EQ(changed[5].rfind("FLASER ", 0), 0u);
        std::swap(changed[5], changed[6]);
      });
  const std::string range_rule =
      "range_0_m: must be in [0.15, 5] m (config.yaml's sensors.sonar range_min_m and "
      "range_max_m), got ";
  const std::vector<std::pair<std::filesystem::path, std::string>> cases = {
      {negative, (negative / "sonar.csv").string() + ":3: " + range_rule + "-5\n"},
      {far, (far / "sonar.csv").string() + ":3: " + range_rule + "1e+300\n"},
      {wide, (wide / "sonar.csv").string() +
                 ": header: expected time_s, then range_0_m .. range_15_m (one column per sonar "
                 "of the ring), got 18 columns\n"},
      {unordered, (unordered / "laser.log").string() +
                      ":7: ipc_timestamp: 0.1 s comes before the previous scan's 0.2 s: a run logs "
                      "its scans in time order\n"},
  };
  for (const auto& [copy, line] : cases) {
    SCOPED_TRACE(copy.string());
    const testing::CliResult result =
        RunPlywood("view " + copy.string() + " --time 0.5 --size 320x200 --screenshot " +
                       (dir / "x.png").string(),
                   dir);
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_EQ(result.err, "plywood: " + line);
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
  // The sonar's own maximum range is a range it can report: the copy is shown.
  const testing::CliResult shown =
      RunPlywood("view " + at_max.string() + " --time 0.5 --size 320x200 --screenshot " +
                     (dir / "x.png").string(),
                 dir);
  EXPECT_EQ(shown.exit_code, 0) << shown.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "x.png"));
}

// audit s34: these were read silently (--time nan showed t = 0, a live run ignored --time,
// --bench-seconds nan "drew 29.6 frames/s" in a run of 0 s, exit 0) or failed after the whole run
// (a screenshot into a missing folder or onto a folder, exit 1). Each is refused before a window
// opens: one line naming the flag, exit 2, nothing written.
TEST_F(ViewCliTest, FlagsThatCannotBeHonouredAreRefusedBeforeAnythingRuns) {
  const std::filesystem::path dir = MakeTempDir("view_cli_flags");
  const std::string experiment = (SourceRoot() / "experiments/default.yaml").string();
  const std::filesystem::path run = OneSecondRun(dir);
  ASSERT_FALSE(::testing::Test::HasFailure());
  const std::string live =
      experiment + " --set duration_s=1 --speed max --exit-at-end --out " + (dir / "live").string();
  const std::string protocol = (SourceRoot() / "experiments/umbmark.yaml").string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {run.string() + " --time nan --screenshot x.png",
       "view: --time: must be a finite number of simulated seconds >= 0, got nan"},
      {run.string() + " --time -5 --screenshot x.png", "view: --time: must be a finite number"},
      {run.string() + " --time 1e999 --screenshot x.png",
       "view: --time: must be a finite number of simulated seconds >= 0, got inf"},
      {live + " --time 5", "view: --time: only a replay (TARGET a run directory)"},
      {"--bench --bench-seconds nan", "view: --bench-seconds: must be in [1, 600]"},
      // s57: CLI11 refused 0.5 in its own words ("Value 0.5 not in range 1.000000 to ..."),
      // and a time past the run's end wrote the last frame as x.png, exit 0.
      {"--bench --bench-seconds 0.5",
       "view: --bench-seconds: must be in [1, 600] simulated seconds, got 0.5"},
      {run.string() + " --time 5 --screenshot x.png",
       "view: --time: " + run.string() + " ends at t = 1 s, got 5; give a time within the run"},
      {run.string() + " --screenshot " + dir.string(),
       "view: --screenshot: " + dir.string() + " is a folder"},
      {live + " --screenshot " + (dir / "no_folder" / "x.png").string(),
       "view: --screenshot: " + (dir / "no_folder" / "x.png").string() + ": no folder"},
      {run.string() + " --size 640x480x3 --screenshot x.png",
       "--size: expected WIDTHxHEIGHT, got '640x480x3'"},
      {run.string() + " --size ' 640x480' --screenshot x.png",
       "--size: expected WIDTHxHEIGHT, got ' 640x480'"},
      {run.string() + " --size 99999999999x100 --screenshot x.png",
       "--size: width_px: must be in [64, 8192], got 99999999999"},
      {run.string() + " --size 640x-480 --screenshot x.png",
       "--size: height_px: must be in [64, 8192], got -480"},
      // audit s37: flags the mode does not read were dropped without a word.
      {run.string() + " --seed 3 --screenshot x.png",
       "view: --seed: only a live run (TARGET an experiment) takes it; " + run.string() +
           " is a run directory, replayed as it was recorded"},
      {run.string() + " --set duration_s=5 --screenshot x.png", "view: --set: only a live run"},
      {run.string() + " --bench --screenshot x.png", "view: --bench: only a live run"},
      {"--bench --out " + (dir / "live").string(),
       "view: --out: --bench runs at 1x with every overlay on and writes no run"},
      {live + " --bench-seconds 5", "view: --bench-seconds: only --bench takes it"},
      // s54: a .jpg name held PNG bytes; the bench ran its 10 s whatever --set duration_s said.
      {run.string() + " --screenshot x.jpg",
       "view: --screenshot: x.jpg: the screenshot is written as PNG; give a name ending in .png"},
      {live + " --screenshot x", "view: --screenshot: x: the screenshot is written as PNG"},
      // s55: a protocol's experiment benched its base run's frames without a word.
      {protocol + " --bench", protocol + ": protocol: plywood view --bench shows single runs only, "
                                         "not protocol 'umbmark'"},
      {"--bench --set duration_s=0.2",
       "view: --set duration_s=0.2: --bench runs --bench-seconds (default 10), not the "
       "experiment's duration_s; give --bench-seconds instead"},
  };
  for (const auto& [args, culprit] : cases) {
    SCOPED_TRACE(args);
    const testing::CliResult result = RunPlywood("view " + args, dir);
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_EQ(result.err.rfind("plywood: " + culprit, 0), 0u) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "live"));
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "x.jpg"));
}

// The titles of the windows on `display` (xwininfo), one a line.
std::string WindowTitles(int display) {
  const std::string command =
      "xwininfo -root -tree -display :" + std::to_string(display) + " 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return "";
  std::string text;
  char buffer[512];
  while (std::fgets(buffer, sizeof(buffer), pipe) != nullptr) text += buffer;
  pclose(pipe);
  return text;
}

// `plywood view ARGS...` on its own Xvfb (started here, DISPLAY restored after), stdout to
// /dev/null, stderr to `err_file`.
struct SpawnedView {
  std::unique_ptr<testing::XvfbDisplay> server;
  pid_t pid = -1;  // -1 once waited for
  SpawnedView() = default;
  SpawnedView(SpawnedView&& other) noexcept
      : server(std::move(other.server)), pid(std::exchange(other.pid, -1)) {}
  ~SpawnedView() {
    if (pid > 0) {  // a test that gave up early: the view must not outlive it
      kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
    }
  }
};
SpawnedView SpawnView(std::vector<std::string> args, const std::string& err_file) {
  SpawnedView view;
  const std::string saved_display = std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "";
  std::string why_not;
  view.server = testing::XvfbDisplay::Start(&why_not);  // its own, to kill; DISPLAY points at it
  EXPECT_TRUE(view.server) << why_not;
  if (!view.server) return view;
  const std::string plywood = (std::filesystem::path(PLYWOOD_BINARY_DIR) / "apps/plywood").string();
  args.insert(args.begin(), {plywood, "view"});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err_file.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  EXPECT_EQ(posix_spawn(&view.pid, plywood.c_str(), &actions, nullptr, argv.data(), ::environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  setenv("DISPLAY", saved_display.c_str(), 1);  // the suite's own display for the other tests
  return view;
}

// Waits for the view until `give_up`; its exit code, or -1 (killed: it did not end, or a signal).
int WaitForExit(SpawnedView& view, std::chrono::steady_clock::time_point give_up) {
  const pid_t pid = view.pid;
  view.pid = -1;
  int status = 0;
  pid_t done = 0;
  while ((done = waitpid(pid, &status, WNOHANG)) == 0 &&
         std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (done == 0) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    ADD_FAILURE() << "plywood view kept running after its window or X server went away";
    return -1;
  }
  EXPECT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// audit s35: an X server killed under a live view ended plywood through Xlib's own handler, "X
// connection to :N broken (explicit kill or server shutdown).", a line naming neither plywood nor
// the view. Now plywood's own line, exit 1 (the run failed; its staging folder is left, as a
// killed run's, for the next run into --out to remove).
TEST_F(ViewCliTest, AnXServerKilledMidViewEndsItWithOneLineOfPlywoods) {
  if (std::system("xwininfo -version >/dev/null 2>&1") != 0) GTEST_SKIP() << "no xwininfo";
  const std::filesystem::path dir = MakeTempDir("view_cli_x_lost");
  const std::string experiment = (SourceRoot() / "experiments/default.yaml").string();
  const std::string out = (dir / "out").string();
  const std::string err_file = (dir / "err.txt").string();
  SpawnedView view = SpawnView(
      {experiment, "--speed", "1", "--quiet", "--size", "320x240", "--out", out}, err_file);
  ASSERT_TRUE(view.server);
  const int display = view.server->display();

  // The window is up (the run is simulating) before the server goes.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!DisplayShowsAWindow(display) && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_TRUE(DisplayShowsAWindow(display)) << "no window within 60 s: " << Slurp(err_file);
  view.server.reset();  // kills the X server by its pid

  EXPECT_EQ(WaitForExit(view, give_up), 1);
  const std::string err = Slurp(err_file);
  EXPECT_EQ(err.rfind("plywood: view: lost the X display :" + std::to_string(display), 0), 0u)
      << err;
  EXPECT_NE(err.find("unfinished: nothing of it is written"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "metrics.json"));
}

// stop 50: a window held on a FINISHED run lost the whole run when the view ended any other way
// than by the close button: the X server killed (or the connection: an ssh -X link dropped) gave
// "... a live run with it, unfinished" and exit 1, a window destroyed by another client Xlib's raw
// BadWindow text; both left an empty run directory. Now one line of plywood's, exit 0, and the run
// directory finished and byte-identical to `plywood run`'s.
TEST_F(ViewCliTest, AFinishedRunIsWrittenWhateverEndsTheViewOfIt) {
  if (std::system("xwininfo -version >/dev/null 2>&1") != 0) GTEST_SKIP() << "no xwininfo";
  const bool xdotool = std::system("xdotool version >/dev/null 2>&1") == 0;
  const std::filesystem::path dir = MakeTempDir("view_cli_finished_x_lost");
  const std::string experiment = (SourceRoot() / "experiments/default.yaml").string();
  const testing::CliResult run = RunPlywood(
      "run " + experiment + " --seed 3 --set duration_s=3 --quiet --out " + (dir / "run").string(),
      dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  struct Ending {
    std::string name;
    std::string line;  // what plywood's one line starts with
  };
  std::vector<Ending> endings = {{"server", "plywood: view: lost the X display :"}};
  if (xdotool) {
    endings.push_back(
        {"windowclose", "plywood: view: the window was destroyed by another X client"});
  } else {
    std::printf("note: no xdotool, the destroyed window is not checked\n");
  }
  for (const Ending& ending : endings) {
    SCOPED_TRACE(ending.name);
    const std::filesystem::path out = dir / ("viewed-" + ending.name);
    const std::string err_file = (dir / ("err-" + ending.name + ".txt")).string();
    SpawnedView view = SpawnView({experiment, "--seed", "3", "--set", "duration_s=3", "--speed",
                                  "max", "--quiet", "--size", "320x240", "--out", out.string()},
                                 err_file);
    ASSERT_TRUE(view.server);
    const int display = view.server->display();
    // The title says the run finished once its record is complete (the window then holds it).
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(90);
    while (WindowTitles(display).find("plywood: run finished") == std::string::npos &&
           std::chrono::steady_clock::now() < give_up) {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    ASSERT_NE(WindowTitles(display).find("plywood: run finished"), std::string::npos)
        << "no finished run within 90 s: " << Slurp(err_file);
    if (ending.name == "server") {
      view.server.reset();  // kills the X server by its pid
    } else {
      const std::string close = "xdotool search --name 'plywood: run finished' windowclose" +
                                std::string(" >/dev/null 2>&1");
      ASSERT_EQ(std::system(("DISPLAY=:" + std::to_string(display) + " " + close).c_str()), 0);
    }
    EXPECT_EQ(WaitForExit(view, give_up), 0);
    const std::string err = Slurp(err_file);
    EXPECT_EQ(err.rfind(ending.line, 0), 0u) << err;
    EXPECT_NE(err.find("the run had finished: its files are written"), std::string::npos) << err;
    EXPECT_EQ(err.find("unfinished"), std::string::npos) << err;
    // One line of the view's (a viewed run's snapshot may add the note that it was drawn in
    // software, as when the window is closed).
    EXPECT_EQ(err.find("plywood: view:", 1), std::string::npos) << err;
    EXPECT_EQ(sim::WhyNotAFinishedRun(out), "");
    for (const char* file :
         {"metrics.json", "trajectory.csv", "laser.log", "sonar.csv", "config.yaml"}) {
      const std::string expected = Slurp(dir / "run" / file);
      EXPECT_FALSE(expected.empty()) << file;
      EXPECT_TRUE(Slurp(out / file) == expected) << file << " differs from plywood run's";
    }
    const render::RgbImage snapshot = render::ReadPng(out / "snapshot.png");
    const render::RgbImage expected = render::ReadPng(dir / "run" / "snapshot.png");
    EXPECT_EQ(snapshot.width, expected.width);
    EXPECT_EQ(snapshot.height, expected.height);
  }
}

// audit s37: without a display the view ended on GLFW's line, exit 1: "plywood: error: viewer:
// cannot start GLFW: X11: The DISPLAY environment variable is missing". Now a usage line with the
// ways out, exit 2, after the target's own checks and before any run folder is made.
TEST_F(ViewCliTest, WithoutADisplayTheViewIsRefusedInOneLineBeforeAnythingRuns) {
  const std::filesystem::path dir = MakeTempDir("view_cli_no_display");
  const std::string experiment = (SourceRoot() / "experiments/default.yaml").string();
  const std::string display = std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "";
  const std::string wayland = std::getenv("WAYLAND_DISPLAY") ? std::getenv("WAYLAND_DISPLAY") : "";
  unsetenv("DISPLAY");
  unsetenv("WAYLAND_DISPLAY");
  const testing::CliResult live = RunPlywood(
      "view " + experiment + " --set duration_s=1 --out " + (dir / "live").string(), dir);
  const testing::CliResult bench = RunPlywood("view --bench", dir);
  const testing::CliResult bad = RunPlywood("view " + experiment + " --set duration_s=-1", dir);
  // s56: --speed and --size were read only once a display was found, so these said "no display".
  const testing::CliResult bad_speed = RunPlywood("view " + experiment + " --speed 0", dir);
  const testing::CliResult bad_size = RunPlywood("view " + experiment + " --size 0x0", dir);
  // s52: a DISPLAY that names no X server ended the view on GLFW's line, exit 1 (a failure during
  // a run), where nothing had run.
  setenv("DISPLAY", ":4093", 1);
  const testing::CliResult no_server = RunPlywood(
      "view " + experiment + " --set duration_s=1 --out " + (dir / "no_server").string(), dir);
  const testing::CliResult no_server_bench = RunPlywood("view --bench", dir);
  unsetenv("DISPLAY");
  if (!display.empty()) setenv("DISPLAY", display.c_str(), 1);
  if (!wayland.empty()) setenv("WAYLAND_DISPLAY", wayland.c_str(), 1);
  for (const testing::CliResult* result : {&live, &bench}) {
    EXPECT_EQ(result->exit_code, 2) << result->err;
    EXPECT_EQ(result->err,
              "plywood: view: no display to open a window on (DISPLAY is not set): run it in a "
              "desktop session or under xvfb-run; plywood run writes the same results without a "
              "window\n");
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "live"));
  for (const testing::CliResult* result : {&no_server, &no_server_bench}) {
    EXPECT_EQ(result->exit_code, 2) << result->err;
    EXPECT_EQ(result->err.rfind("plywood: view: cannot open a window on DISPLAY ':4093' (", 0), 0u)
        << result->err;
    EXPECT_NE(result->err.find("under xvfb-run"), std::string::npos) << result->err;
    EXPECT_EQ(std::count(result->err.begin(), result->err.end(), '\n'), 1) << result->err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "no_server"));
  // A bad experiment is still named first.
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  EXPECT_NE(bad.err.find("duration_s: must be a finite number > 0"), std::string::npos) << bad.err;
  EXPECT_EQ(bad_speed.exit_code, 2) << bad_speed.err;
  EXPECT_EQ(bad_speed.err, "plywood: --speed: expected 1, 10 or max, got '0'\n");
  EXPECT_EQ(bad_size.exit_code, 2) << bad_size.err;
  EXPECT_EQ(bad_size.err, "plywood: --size: width_px: must be in [64, 8192], got 0\n");
}

}  // namespace
}  // namespace plywood
