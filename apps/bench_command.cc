#include "apps/bench_command.h"

#include <cstdio>

#include "apps/command_line.h"
#include "eval/lines/line_bench.h"
#include "sim/config/experiment_config.h"
#include "sim/config/robot_catalog.h"
#include "sim/raycast/ray_caster_bench.h"
#include "sim/runner/experiment_runner.h"

namespace plywood::apps {

int BenchCommand(const std::vector<std::string>& args) {
  const CommandLine line(args, {"--seconds", "--world"}, {});
  if (!line.positional().empty())
    throw UsageError{"usage: plywood bench [--seconds S] [--world PATH]"};
  const double seconds = line.Number("--seconds").value_or(120.0);
  const std::string world = line.Value("--world").value_or("worlds/office.xml");

  // The benchmark's experiment is spelled in YAML like any other, so it exercises the real path.
  const std::string yaml =
      "name: bench\nseed: 1\nduration_s: " + std::to_string(seconds) + "\nworld: " + world +
      "\nrobot: {model: p3dx}\n"
      "controller: {type: wall_following, sensor: sonar, side: left, distance_m: 0.6}\n"
      "sensors:\n"
      "  laser: {resolution_deg: 0.5, rate_hz: 10}\n"
      "  sonar: {rate_hz: 10}\n"
      "  encoders: {}\n"
      "  gyro: {}\n";
  const sim::ExperimentConfig config =
      sim::ParseExperimentConfig(yaml, "bench", std::filesystem::current_path());

  sim::ExperimentRunner runner(config);
  runner.Run();
  const sim::RunCost& cost = runner.cost();
  const double rays_per_s = cost.rays / cost.wall_s;

  const sim::RayCasterBenchResult rays =
      sim::RunRayCasterBench(runner.scene().model(), runner.scene().data(), 200000, 1);
  std::printf("plywood bench: P3-DX, LMS 200 (361 beams @ 10 Hz) + 16 sonars @ 10 Hz, %s, 1 core\n",
              config.world_path.filename().c_str());
  std::printf("%-28s %10.1f s\n", "simulated", cost.simulated_s);
  std::printf("%-28s %10.3f s\n", "wall", cost.wall_s);
  std::printf("%-28s %10.0f x\n", "real-time factor", cost.RealTimeFactor());
  std::printf("%-28s %10.0f\n", "rays per wall second", rays_per_s);
  std::printf("%-28s %10.3f us\n", "physics step (incl. sensors)", 1e6 * cost.wall_s / cost.steps);
  std::printf("%-28s %10.3f us  (%d geoms)\n", "mj_ray per ray", rays.mj_ray_us_per_ray,
              rays.world_geoms);
  std::printf("%-28s %10.3f us\n", "grid caster per ray", rays.grid_us_per_ray);
  eval::PrintLineExtractorBench();
  return 0;
}

}  // namespace plywood::apps
