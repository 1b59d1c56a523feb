#include "eval/bench/bench_experiment.h"

#include "sim/config/experiment_config.h"
#include "sim/runner/format_number.h"

namespace plywood::eval {

BenchFigures RunBench(const BenchOptions& options) {
  const std::string yaml =
      "name: bench\nseed: 1\nduration_s: " + sim::FormatNumber(options.seconds) +
      "\nworld: " + options.world +
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
  BenchFigures figures;
  figures.world = config.world_path;
  figures.cost = runner.cost();
  figures.rays_per_wall_s = figures.cost.rays / figures.cost.wall_s;
  figures.physics_step_us = 1e6 * figures.cost.wall_s / static_cast<double>(figures.cost.steps);
  figures.rays = sim::RunRayCasterBench(runner.scene().model(), runner.scene().data(), 200000, 1);
  figures.lines = MeasureLineExtractors();
  return figures;
}

}  // namespace plywood::eval
