// plywood bench [--seconds S] [--world PATH] [--repeats N] [--min-wall S]

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>

#include "apps/command.h"
#include "apps/decimal_whole_number.h"
#include "eval/bench/bench_experiment.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/format_number.h"

namespace plywood::apps {
namespace {

double UsPerStep(double seconds, long steps) { return steps > 0 ? 1e6 * seconds / steps : 0.0; }

// The 1-minute load average now ("n/a" where the system does not tell): every wall-clock figure
// is only as good as the share of a core the machine left it.
std::string LoadAverage() {
  double load[1];
  if (getloadavg(load, 1) != 1) return "n/a";
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f", load[0]);
  return text;
}

void PrintFigures(const eval::BenchFigures& f, const eval::BenchOptions& o) {
  std::printf(
      "plywood bench: P3-DX, LMS 200 (361 beams @ 10 Hz) + 16 sonars @ 10 Hz, wall following, 1 "
      "core; each figure the fastest of %d repetitions of >= %.1f s wall; load average %s\n",
      o.repeats, o.min_wall_s, LoadAverage().c_str());
  const eval::WorldSpeed& w = f.itemised;
  const sim::StepPartTimes& p = w.parts;
  std::printf("%s: %.0f x real time, %.1f s simulated in %.3f s wall, %ld steps, %d geoms\n",
              w.label.c_str(), w.cost.RealTimeFactor(), w.cost.simulated_s, w.cost.wall_s,
              w.cost.steps, w.geoms);
  std::printf("  per step (us):\n");
  const double timed =
      p.physics_s + p.laser_s + p.sonar_s + p.controller_s + p.recording_s + p.other_s;
  const std::pair<const char*, double> parts[] = {{"physics (mj_step)", p.physics_s},
                                                  {"laser", p.laser_s},
                                                  {"sonar", p.sonar_s},
                                                  {"controller", p.controller_s},
                                                  {"recording", p.recording_s},
                                                  {"encoders, gyro, estimators", p.other_s},
                                                  {"untimed (loop, timers)", w.cost.wall_s - timed},
                                                  {"total", w.cost.wall_s}};
  for (const auto& [name, seconds] : parts) {
    std::printf("    %-28s %8.2f\n", name, UsPerStep(seconds, w.cost.steps));
  }
  std::printf("  %-30s %8.0f\n", "rays per wall second", w.cost.rays / w.cost.wall_s);
  std::printf("real-time factor (no part timers), load average %s:\n", LoadAverage().c_str());
  for (const eval::WorldSpeed& s : f.worlds) {
    std::printf("  %-28s %8.0f x  (%.2f us/step, %d geoms)\n", s.label.c_str(),
                s.cost.RealTimeFactor(), UsPerStep(s.cost.wall_s, s.cost.steps), s.geoms);
  }
  // worlds: hall, office, tiled office, then the planar office and tiled office.
  const auto print_ratio = [&](const char* label, std::size_t tiled, std::size_t office) {
    if (f.worlds.size() <= tiled || f.worlds[office].cost.RealTimeFactor() <= 0.0) return;
    std::printf("  %-28s %8.2f   (the goal: >= 0.8)\n", label,
                f.worlds[tiled].cost.RealTimeFactor() / f.worlds[office].cost.RealTimeFactor());
  };
  print_ratio("3x3 tiled / office RTF", 2, 1);
  print_ratio("the same, planar drive", 4, 3);
  std::printf("%-30s %8.3f us  (%d geoms)\n", "mj_ray per ray", f.rays.mj_ray_us_per_ray,
              f.rays.world_geoms);
  std::printf("%-30s %8.3f us\n", "grid caster per ray", f.rays.grid_us_per_ray);
  std::printf("line extraction, 361-beam scan (%zu points), 1 core:\n", f.lines.scan_points);
  for (const eval::LineExtractorSpeed& e : f.lines.extractors) {
    std::printf("  %-28s %8.0f scans/s  (%.1f lines per scan)\n", e.name.c_str(), e.scans_per_s,
                e.lines_per_scan);
  }
  std::printf(
      "plywood run experiments/default.yaml: %.3f s wall for %.1f s simulated (%.0f x, "
      "outputs and snapshot included)\n",
      f.default_run_wall_s, f.default_run_simulated_s,
      f.default_run_simulated_s / f.default_run_wall_s);
  std::printf(
      "  its simulation alone: %.3f s wall; the run takes %.2f x that (the goal: <= 1.5; both the "
      "fastest of %d); load average %s\n",
      f.default_run_simulation_wall_s, f.default_run_wall_s / f.default_run_simulation_wall_s,
      f.default_run_repeats, LoadAverage().c_str());
}

}  // namespace

Command AddBenchCommand(CLI::App& app) {
  auto options = std::make_shared<eval::BenchOptions>();
  CLI::App* cli = app.add_subcommand(
      "bench",
      "Print the real-time factor and ray throughput of a P3-DX with an LMS 200 and 16 sonars "
      "wall-following on one core (per-part costs per step; hall, office and a 3x3 tiled office), "
      "the "
      "ray casters, every line extractor and a default plywood run (figures only)");
  cli->add_option("--seconds", options->seconds, "simulated seconds of wall following")
      ->type_name("S")
      ->capture_default_str();
  cli->add_option("--world", options->world, "MJCF room to run in")
      ->type_name("PATH")
      ->capture_default_str();
  cli->add_option("--repeats", options->repeats, "repetitions per figure; the fastest is printed")
      ->type_name("N")
      ->transform(DecimalWholeNumber())
      ->capture_default_str();
  cli->add_option("--min-wall", options->min_wall_s,
                  "wall seconds each repetition runs at least (whole runs of --seconds)")
      ->type_name("S")
      ->capture_default_str();
  cli->footer("Example:\n  plywood bench --seconds 30 --world worlds/hall.xml --repeats 5");
  return {cli, [options] {
            // Bounded so that a typo fails at once instead of benchmarking for ever (fuzz30:
            // --min-wall 1e300 ran until killed).
            if (!std::isfinite(options->seconds)) {
              throw UsageError("bench: --seconds: must be a finite number");
            }
            if (!(options->seconds > 0.0 && options->seconds <= 1e5)) {
              throw UsageError("bench: --seconds: must be in (0, 1e5] simulated seconds, got " +
                               sim::FormatNumber(options->seconds));
            }
            // Shorter than one step simulates nothing: 0 x real time, "-nan" rays per second.
            const double step_s = sim::PhysicsOptions{}.timestep_s;
            if (options->seconds < step_s) {
              throw UsageError("bench: --seconds: must be at least one physics step (" +
                               sim::FormatNumber(step_s) + " s), got " +
                               sim::FormatNumber(options->seconds));
            }
            if (options->repeats < 1 || options->repeats > 1000) {
              throw UsageError("bench: --repeats: must be in 1..1000, got " +
                               std::to_string(options->repeats));
            }
            if (!(options->min_wall_s >= 0.0) || !std::isfinite(options->min_wall_s)) {
              throw UsageError("bench: --min-wall: must be a finite number >= 0");
            }
            if (options->min_wall_s > 3600.0) {
              throw UsageError("bench: --min-wall: must be at most 3600 wall seconds, got " +
                               sim::FormatNumber(options->min_wall_s));
            }
            PrintFigures(eval::RunBench(*options), *options);
            return 0;
          }};
}

}  // namespace plywood::apps
