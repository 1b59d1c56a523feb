// plywood bench [--seconds S] [--world PATH]

#include <cmath>
#include <cstdio>
#include <memory>

#include "apps/command.h"
#include "eval/bench/bench_experiment.h"

namespace plywood::apps {
namespace {

void PrintFigures(const eval::BenchFigures& f) {
  std::printf("plywood bench: P3-DX, LMS 200 (361 beams @ 10 Hz) + 16 sonars @ 10 Hz, %s, 1 core\n",
              f.world.filename().c_str());
  std::printf("%-28s %10.1f s\n", "simulated", f.cost.simulated_s);
  std::printf("%-28s %10.3f s\n", "wall", f.cost.wall_s);
  std::printf("%-28s %10.0f x\n", "real-time factor", f.cost.RealTimeFactor());
  std::printf("%-28s %10.0f\n", "rays per wall second", f.rays_per_wall_s);
  std::printf("%-28s %10.3f us\n", "physics step (incl. sensors)", f.physics_step_us);
  std::printf("%-28s %10.3f us  (%d geoms)\n", "mj_ray per ray", f.rays.mj_ray_us_per_ray,
              f.rays.world_geoms);
  std::printf("%-28s %10.3f us\n", "grid caster per ray", f.rays.grid_us_per_ray);
  std::printf("line extraction, 361-beam scan (%zu points), 1 core:\n", f.lines.scan_points);
  for (const eval::LineExtractorSpeed& e : f.lines.extractors) {
    std::printf("  %-26s %10.0f scans/s  (%.1f lines per scan)\n", e.name.c_str(), e.scans_per_s,
                e.lines_per_scan);
  }
}

}  // namespace

Command AddBenchCommand(CLI::App& app) {
  auto options = std::make_shared<eval::BenchOptions>();
  CLI::App* cli = app.add_subcommand(
      "bench",
      "Print the real-time factor and ray throughput of a P3-DX with an LMS 200 and 16 sonars "
      "wall-following on one core, and the speed of every line extractor (figures only)");
  cli->add_option("--seconds", options->seconds, "simulated seconds of wall following")
      ->type_name("S")
      ->capture_default_str();
  cli->add_option("--world", options->world, "MJCF room to run in")
      ->type_name("PATH")
      ->capture_default_str();
  cli->footer("Example:\n  plywood bench --seconds 30 --world worlds/hall.xml");
  return {cli, [options] {
            if (!std::isfinite(options->seconds)) {
              throw UsageError("bench: --seconds: must be a finite number");
            }
            PrintFigures(eval::RunBench(*options));
            return 0;
          }};
}

}  // namespace plywood::apps
