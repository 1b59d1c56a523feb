// plywood view EXPERIMENT.yaml [--seed N] [--set KEY.PATH=VALUE]... [--out DIR] [--force]
//                              [--speed 1|10|max] [--paused] [--exit-at-end] [--screenshot PNG]
//                              [--size WxH] [--no-panel] [--quiet]
// plywood view RUN_DIR [--time T] [--screenshot PNG] [--size WxH]
// plywood view --bench [EXPERIMENT.yaml] [--bench-seconds S]

#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "apps/command.h"
#include "apps/seed_flag.h"
#include "eval/protocol.h"
#include "msgs/shortest_number.h"
#include "plywood_paths.h"
#include "render/png_image.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/run_directory.h"

#if PLYWOOD_HAS_VIEWER
#include "viewer/display_probe.h"
#include "viewer/live_viewer.h"
#include "viewer/run_replay.h"
#endif

namespace plywood::apps {
namespace {

#if PLYWOOD_HAS_VIEWER
struct ViewFlags {
  std::string target;
  std::string out;
  std::string seed;
  std::vector<std::string> overrides;
  std::string speed = "1";
  std::string size = "1280x800";
  std::string screenshot;
  double time_s = -1.0;
  double bench_seconds = 10.0;
  bool paused = false;
  bool exit_at_end = false;
  bool no_panel = false;
  bool quiet = false;
  bool force = false;
  bool bench = false;
};

// All of WIDTHxHEIGHT, digits only: sscanf("%dx%d") took "640x480x3" and " 640x480", and
// wrapped 99999999999 into 1215752191.
viewer::WindowOptions WindowOf(const ViewFlags& flags) {
  viewer::WindowOptions window;
  const std::string& size = flags.size;
  const auto parse = [&](std::size_t begin, std::size_t end, int& px, const char* field) {
    long long value = 0;
    const auto [ptr, error] = std::from_chars(size.data() + begin, size.data() + end, value);
    if (begin == end || error == std::errc::invalid_argument || ptr != size.data() + end) {
      throw UsageError("--size: expected WIDTHxHEIGHT, got '" + size + "'");
    }
    if (error == std::errc::result_out_of_range || value < INT_MIN || value > INT_MAX) {
      throw UsageError(std::string("--size: ") + field + ": must be in [64, 8192], got " +
                       size.substr(begin, end - begin));
    }
    px = static_cast<int>(value);
  };
  const std::size_t x = size.find('x');
  if (x == std::string::npos) {
    throw UsageError("--size: expected WIDTHxHEIGHT, got '" + size + "'");
  }
  parse(0, x, window.width_px, "width_px");
  parse(x + 1, size.size(), window.height_px, "height_px");
  try {
    window.Validate();
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--size: ") + e.what());
  }
  window.panel = !flags.no_panel;
  return window;
}

// Checked before a window opens or a run starts: CLI11's range check lets NaN through
// (--bench-seconds nan "drew 29.6 frames/s" of a run of 0 s), a --time a live run ignores or a
// NaN one (shown as 0) read silently, and a screenshot that cannot be written failed only after
// the whole run, with exit 1.
void CheckViewFlags(const ViewFlags& flags, bool time_given, bool replay) {
  if (!(flags.bench_seconds >= 1.0 && flags.bench_seconds <= 600.0)) {
    throw UsageError("view: --bench-seconds: must be in [1, 600] simulated seconds, got " +
                     msgs::ShortestNumber(flags.bench_seconds));
  }
  if (time_given && !replay) {
    throw UsageError("view: --time: only a replay (TARGET a run directory) starts at a time; " +
                     flags.target + " is an experiment");
  }
  if (time_given && !(std::isfinite(flags.time_s) && flags.time_s >= 0.0)) {
    throw UsageError("view: --time: must be a finite number of simulated seconds >= 0, got " +
                     msgs::ShortestNumber(flags.time_s));
  }
  if (flags.screenshot.empty()) return;
  const std::filesystem::path picture = flags.screenshot;
  std::error_code error;
  if (std::filesystem::is_directory(picture, error)) {
    throw UsageError("view: --screenshot: " + flags.screenshot +
                     " is a folder; give the PNG file's name");
  }
  // The frame is encoded as PNG whatever the name says: `shot.jpg` held PNG bytes (s54).
  std::string extension = picture.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".png") {
    throw UsageError("view: --screenshot: " + flags.screenshot +
                     ": the screenshot is written as PNG; give a name ending in .png");
  }
  const std::filesystem::path folder = picture.has_parent_path() ? picture.parent_path() : ".";
  if (!std::filesystem::is_directory(folder, error)) {
    throw UsageError("view: --screenshot: " + flags.screenshot + ": no folder " + folder.string() +
                     " to write it in");
  }
}

// A flag the chosen mode does not read was dropped without a word: `view RUN --seed 3` or `--set
// duration_s=5` replayed the run as it was, `view RUN --bench` replayed instead of benchmarking,
// `--bench --out DIR` wrote nothing there, `--bench-seconds 60` without --bench ran the
// experiment's own duration.
void RefuseFlagsTheModeIgnores(const CLI::App& cli, const ViewFlags& flags, bool replay) {
  const auto refuse_given = [&](std::initializer_list<const char*> names, const std::string& why) {
    for (const char* name : names) {
      if (cli.count(name) > 0) throw UsageError("view: " + std::string(name) + ": " + why);
    }
  };
  if (replay) {
    refuse_given({"--bench", "--bench-seconds", "--seed", "--set", "--out", "--force", "--speed",
                  "--paused", "--exit-at-end"},
                 "only a live run (TARGET an experiment) takes it; " + flags.target +
                     " is a run directory, replayed as it was recorded");
    return;
  }
  if (flags.bench) {
    refuse_given({"--out", "--force", "--screenshot", "--speed", "--paused", "--exit-at-end"},
                 "--bench runs at 1x with every overlay on and writes no run; leave it out");
    // The bench lasts --bench-seconds, never the experiment's duration_s: `--set duration_s=0.2`
    // ran the bench's 10 s without a word (s54).
    for (const std::string& assignment : flags.overrides) {
      if (assignment.rfind("duration_s=", 0) == 0) {
        throw UsageError("view: --set " + assignment +
                         ": --bench runs --bench-seconds (default 10), not the experiment's "
                         "duration_s; give --bench-seconds instead");
      }
    }
    return;
  }
  refuse_given({"--bench-seconds"}, "only --bench takes it (a live run lasts duration_s)");
}

viewer::Speed SpeedOf(const std::string& text) {
  if (text == "1") return viewer::Speed::kRealTime;
  if (text == "10") return viewer::Speed::kTenTimes;
  if (text == "max") return viewer::Speed::kUnlimited;
  throw UsageError("--speed: expected 1, 10 or max, got '" + text + "'");
}

// Without a display GLFW's own line ended the view, exit 1: "plywood: error: viewer: cannot start
// GLFW: X11: The DISPLAY environment variable is missing". A missing display is known before any
// window: refused as the usage it is, with the ways out, after the target's own checks.
void RequireDisplay() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((x11 == nullptr || *x11 == '\0') && (wayland == nullptr || *wayland == '\0')) {
    throw UsageError(
        "view: no display to open a window on (DISPLAY is not set): run it in a desktop session "
        "or under xvfb-run; plywood run writes the same results without a window");
  }
  // A DISPLAY that names no server (s52: ":99" with no X on it) ended the view on GLFW's line,
  // exit 1, "a failure during a run", where nothing had run: the environment is the bad input.
  if (const auto problem = viewer::DisplayProblem()) {
    const std::string named = x11 != nullptr && *x11 != '\0'
                                  ? "DISPLAY '" + std::string(x11) + "'"
                                  : "WAYLAND_DISPLAY '" + std::string(wayland) + "'";
    throw UsageError("view: cannot open a window on " + named + " (" + *problem +
                     "): run it in a desktop session or under xvfb-run; plywood run writes the "
                     "same results without a window");
  }
}

int Replay(const ViewFlags& flags) {
  viewer::RunReplayData data = viewer::LoadRunReplay(flags.target);
  // A time past the end showed the last frame, and --screenshot wrote it as if asked (s57).
  if (flags.time_s > data.end_s()) {
    throw UsageError("view: --time: " + flags.target +
                     " ends at t = " + msgs::ShortestNumber(data.end_s()) + " s, got " +
                     msgs::ShortestNumber(flags.time_s) + "; give a time within the run");
  }
  RequireDisplay();
  viewer::ReplayViewer replay(std::move(data), WindowOf(flags));
  if (flags.screenshot.empty()) {
    if (flags.time_s >= 0.0) replay.controls().set_paused(true);
    if (flags.time_s >= 0.0) replay.ShowAt(flags.time_s);
    replay.Run();
    return 0;
  }
  replay.window().SetCapture(true);
  replay.ShowAt(flags.time_s >= 0.0 ? flags.time_s : 0.0);
  render::WritePng(replay.window().Screenshot(), flags.screenshot);
  if (!flags.quiet)
    std::printf("wrote %s (t = %.3f s)\n", flags.screenshot.c_str(), replay.time_s());
  return 0;
}

// Frames per second of the live viewer at 1x with every overlay on, without writing a run.
int Bench(const ViewFlags& flags, const sim::ExperimentConfig& loaded) {
  sim::ExperimentConfig config = loaded;
  config.duration_s = flags.bench_seconds;
  // Every overlay on means something to draw in each: without a `lines:` section the extracted
  // lines overlay would be empty, so the bench extracts lines with split_and_merge.
  if (!config.lines.given && config.sensors.laser) {
    config.lines.given = true;
    config.lines.extractors = {"split_and_merge"};
  }
  sim::ExperimentRunner runner(config);
  viewer::LiveViewerOptions options;
  options.window = WindowOf(flags);
  options.max_fps = 0.0;  // draw at every chance: the figure is what the machine can draw
  options.hold_at_end = false;
  viewer::LiveViewer live(options);
  live.Open(runner);
  live.controls().SetAllOverlays(true);
  runner.SetObserver(&live);
  const auto start = std::chrono::steady_clock::now();
  runner.Run();
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%-28s %s (%s)\n", "viewer bench", config.name.c_str(),
              config.world_path.filename().c_str());
  std::printf("%-28s %.2f s simulated in %.2f s wall at 1x, every overlay on, %dx%d\n", "run",
              runner.scene().time_s(), wall_s, options.window.width_px, options.window.height_px);
  std::printf("%-28s %.1f frames/s (%ld frames)\n", "frames drawn", live.frames_drawn() / wall_s,
              live.frames_drawn());
  return 0;
}

int Live(const ViewFlags& flags, const sim::ExperimentConfig& config) {
  const std::filesystem::path out_dir =
      flags.out.empty() ? "runs/" + config.name + "-seed" + std::to_string(config.seed) : flags.out;
  viewer::LiveViewerOptions options;
  options.window = WindowOf(flags);
  options.speed = SpeedOf(flags.speed);
  options.start_paused = flags.paused;
  options.final_screenshot = flags.screenshot;
  options.hold_at_end = !flags.exit_at_end;
  viewer::LiveViewer live(options);
  const bool snapshots = config.output.snapshot;
  const eval::ProtocolContext context{.config = config,
                                      .out_dir = out_dir,
                                      .quiet = flags.quiet,
                                      .snapshots = snapshots,
                                      .force = flags.force,
                                      .observer = &live};
  // The viewer runs the run exactly as `plywood run` does: same protocol, same writers.
  const int code = eval::RunProtocol(context);
  if (!flags.screenshot.empty() && !flags.quiet)
    std::printf("wrote %s\n", flags.screenshot.c_str());
  return code;
}
#endif

}  // namespace

Command AddViewCommand(CLI::App& app) {
  CLI::App* cli = app.add_subcommand(
      "view", "Watch an experiment run live (or replay a finished run) in a window");
#if PLYWOOD_HAS_VIEWER
  auto flags = std::make_shared<ViewFlags>();
  cli->add_option("TARGET", flags->target,
                  "experiment YAML file to run live, or a run directory to replay");
  cli->add_option("--out", flags->out, "results directory of the live run (as plywood run)")
      ->type_name("DIR")
      ->default_str("runs/NAME-seedSEED");
  CLI::Option* seed =
      cli->add_option("--seed", flags->seed, "seed of every random draw")->type_name("N");
  cli->add_option("--set", flags->overrides, "override one key of the experiment (repeatable)")
      ->type_name("KEY.PATH=VALUE")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cli->add_flag("--force", flags->force, "replace an earlier run in --out");
  cli->add_option("--speed", flags->speed, "1 (real time), 10, or max")->default_str("1");
  cli->add_flag("--paused", flags->paused, "start paused (Space resumes, N steps)");
  cli->add_flag("--exit-at-end", flags->exit_at_end,
                "close the window when the run ends (otherwise it stays until closed; the results "
                "are written then)");
  cli->add_option("--screenshot", flags->screenshot,
                  "write the final frame (replay: the frame at --time) as PNG and close")
      ->type_name("PNG");
  CLI::Option* time =
      cli->add_option("--time", flags->time_s, "replay: start at this simulated time")
          ->type_name("S");
  cli->add_option("--size", flags->size, "window size")->type_name("WxH")->default_str("1280x800");
  cli->add_flag("--no-panel", flags->no_panel, "no Dear ImGui panel");
  cli->add_flag("--quiet", flags->quiet, "no progress and no summary");
  cli->add_flag("--bench", flags->bench,
                "frames/s at 1x with every overlay on (default experiment: the office); writes "
                "no run");
  // The range is CheckViewFlags's (CLI11's printed "not in range 1.000000 to 600.000000").
  cli->add_option("--bench-seconds", flags->bench_seconds,
                  "simulated seconds of --bench, in [1, 600]")
      ->default_str("10");
  cli->footer(
      "Keys: F1 help, Space pause, N step, 1/2/3 speed, arrows drive (H hands back), L S I P E M "
      "G B\n"
      "overlays, T/F top-down/follow camera, V record video. Mouse: orbit, pan (right), zoom.\n"
      "Examples:\n"
      "  plywood view experiments/default.yaml\n"
      "  plywood view runs/default-seed1 --time 30\n"
      "  plywood view --bench");
  return {cli, [cli, flags, seed, time] {
            if (flags->bench && flags->target.empty()) {
              flags->target = std::string(PLYWOOD_SOURCE_ROOT) + "/experiments/default.yaml";
            }
            if (flags->target.empty()) throw UsageError("view: TARGET is required");
            const bool replay = std::filesystem::is_directory(flags->target);
            RefuseFlagsTheModeIgnores(*cli, *flags, replay);
            CheckViewFlags(*flags, time->count() > 0, replay);
            // --size and --speed were parsed only once the display was found: without one,
            // `--speed 0` or `--size 0x0` read "no display", the bad flag unnamed (s56).
            WindowOf(*flags);
            if (!replay && !flags->bench) SpeedOf(flags->speed);
            if (replay) return Replay(*flags);
            const std::vector<std::string> overrides =
                WithSeedFlag(flags->overrides, *seed, flags->seed, "view");
            const sim::ExperimentConfig config =
                sim::LoadExperimentConfig(flags->target, overrides);
            // The bench, as a live run, shows one run: `view umbmark.yaml --bench` benched its
            // base experiment's single run and said nothing of the protocol (s55).
            eval::RequireObservableProtocol(config,
                                            flags->bench ? "plywood view --bench" : "plywood view");
            RequireDisplay();
            return flags->bench ? Bench(*flags, config) : Live(*flags, config);
          }};
#else
  // Whatever follows `view` (an experiment, a run directory, any flag) gets the same one line.
  cli->prefix_command();
  return {cli,
          [] {
            throw UsageError(
                "view: this build has no viewer (configure with GLFW and OpenGL found and "
                "-DPLYWOOD_VIEWER=ON)");
            return 2;
          },
          /*takes_any_arguments=*/true};
#endif
}

}  // namespace plywood::apps
