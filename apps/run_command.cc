// plywood run EXPERIMENT.yaml [--out DIR] [--seed N] [--set KEY.PATH=VALUE]... [--quiet]
//                             [--no-snapshot] [--force] [--video OUT.mp4 [--video-fps N]]

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "apps/command.h"
#include "apps/seed_flag.h"
#include "eval/protocol.h"
#include "eval/score/rerun_world_check.h"
#include "msgs/shortest_number.h"
#include "render/video_recorder.h"
#include "sim/config/experiment_config.h"

namespace plywood::apps {
namespace {

// Checked before the run: ffmpeg would only fail at the first frame, after part of the run, with
// its own line on stderr and then two of ours (exit 1). CLI11's range check lets NaN through.
void RequireWritableVideo(const std::filesystem::path& video, double fps) {
  if (!(fps >= 1.0 && fps <= 60.0)) {
    throw UsageError("run: --video-fps: must be in [1, 60] frames per simulated second, got " +
                     msgs::ShortestNumber(fps));
  }
  std::error_code error;
  if (std::filesystem::is_directory(video, error)) {
    throw UsageError("--video: " + video.string() + " is a folder; give the video file's name");
  }
  const std::filesystem::path folder = video.has_parent_path() ? video.parent_path() : ".";
  if (!std::filesystem::is_directory(folder, error)) {
    throw UsageError("--video: " + video.string() + ": no folder " + folder.string() +
                     " to write it in");
  }
}

// The run is written into OUT.partial-PID and moved to OUT when it ends: a video inside OUT
// (or OUT itself) made that move fail after the whole run ("cannot move the finished run into
// place", or with --force "changed while the run was going"), exit 2, the results left in the
// .partial folder (s61).
void RequireVideoOutsideTheRunFolder(const std::filesystem::path& video,
                                     const std::filesystem::path& out_dir) {
  const auto resolved = [](const std::filesystem::path& path) {
    std::filesystem::path p = std::filesystem::weakly_canonical(std::filesystem::absolute(path));
    return p.has_filename() ? p : p.parent_path();  // `runs/x/` names the folder runs/x
  };
  const std::filesystem::path folder = resolved(out_dir);
  const std::filesystem::path file = resolved(video);
  const auto [end_of_folder, rest] =
      std::mismatch(folder.begin(), folder.end(), file.begin(), file.end());
  if (end_of_folder != folder.end()) return;
  throw UsageError("--video: " + video.string() + " is inside the run's folder " +
                   out_dir.string() +
                   " (--out), which the run writes whole when it ends: write the video elsewhere");
}

}  // namespace

Command AddRunCommand(CLI::App& app) {
  struct Flags {
    std::string experiment;
    std::string out;
    std::string seed;
    std::vector<std::string> overrides;
    bool quiet = false;
    bool no_snapshot = false;
    bool force = false;
    std::string video;
    double video_fps = 10.0;
  };
  auto flags = std::make_shared<Flags>();
  CLI::App* cli = app.add_subcommand(
      "run", "Run one experiment (or its protocol's runs) and write its results to a directory");
  cli->add_option("EXPERIMENT", flags->experiment, "experiment YAML file (docs/experiments.md)")
      ->required();
  cli->add_option("--out", flags->out, "results directory (docs/run_outputs.md)")
      ->type_name("DIR")
      ->default_str("runs/NAME-seedSEED");
  CLI::Option* seed = cli->add_option("--seed", flags->seed,
                                      "seed of every random draw (default: the experiment's seed:)")
                          ->type_name("N");
  cli->add_option("--set", flags->overrides,
                  "override one key of the experiment, e.g. robot.spawn.x_m=1 (repeatable)")
      ->type_name("KEY.PATH=VALUE")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cli->add_flag("--quiet", flags->quiet, "no progress and no summary");
  cli->add_flag("--no-snapshot", flags->no_snapshot,
                "write no pictures (as output.snapshot: false)");
  cli->add_flag("--force", flags->force,
                "replace an earlier run in --out (a directory with its config.yaml and "
                "metrics.json); refused if it holds any file a run does not write");
  CLI::Option* video =
      cli->add_option("--video", flags->video,
                      "also record the run as an MP4 (top-down, offscreen; needs ffmpeg)")
          ->type_name("OUT.mp4");
  // Without --video no frame is drawn: the rate was dropped without a word, exit 0 (s61).
  cli->add_option("--video-fps", flags->video_fps, "video frames per simulated second")
      ->check(CLI::Range(1.0, 60.0))
      ->default_str("10")
      ->needs(video);
  cli->footer(
      "Examples:\n"
      "  plywood run experiments/default.yaml\n"
      "  plywood run experiments/default.yaml --out runs/demo --seed 2 --set duration_s=30 "
      "--force\n"
      "  plywood run experiments/default.yaml --set duration_s=20 --video default.mp4");
  return {cli, [flags, seed] {
            const std::vector<std::string> overrides =
                WithSeedFlag(flags->overrides, *seed, flags->seed, "run");
            const sim::ExperimentConfig config =
                sim::LoadExperimentConfig(flags->experiment, overrides);
            eval::RequireWorldOfARerunUnchanged(flags->experiment, overrides);
            const std::filesystem::path out_dir =
                flags->out.empty() ? "runs/" + config.name + "-seed" + std::to_string(config.seed)
                                   : flags->out;
            eval::FindProtocol(config);  // an unknown protocol must not cost an earlier run
            std::unique_ptr<render::VideoRecorder> video;
            if (!flags->video.empty()) {
              if (std::filesystem::path(flags->video).extension() != ".mp4") {
                throw UsageError("--video: expected a file name ending in .mp4, got '" +
                                 flags->video + "'");
              }
              RequireWritableVideo(flags->video, flags->video_fps);
              RequireVideoOutsideTheRunFolder(flags->video, out_dir);
              eval::RequireObservableProtocol(config, "--video");
              video = std::make_unique<render::VideoRecorder>(
                  flags->video, render::VideoOptions{.fps = flags->video_fps});
            }
            const bool snapshots = config.output.snapshot && !flags->no_snapshot;
            const int code = eval::RunProtocol(eval::ProtocolContext{.config = config,
                                                                     .out_dir = out_dir,
                                                                     .quiet = flags->quiet,
                                                                     .snapshots = snapshots,
                                                                     .force = flags->force,
                                                                     .observer = video.get()});
            if (video && !flags->quiet) {
              std::printf("%-34s %s (%ld frames)\n", "video", flags->video.c_str(),
                          video->frames());
            }
            return code;
          }};
}

}  // namespace plywood::apps
