#pragma once

#include <filesystem>
#include <string>

#include "eval/lines/line_bench.h"
#include "sim/raycast/ray_caster_bench.h"
#include "sim/runner/experiment_runner.h"

namespace plywood::eval {

struct BenchOptions {
  double seconds = 120.0;                   // simulated seconds of wall following
  std::string world = "worlds/office.xml";  // MJCF room, as an experiment's `world:` spells it
};

// What `plywood bench` measured: wall-clock figures, so they differ from run to run.
struct BenchFigures {
  std::filesystem::path world;  // the resolved world file
  sim::RunCost cost;            // of the whole run: physics, sensors, estimators
  double rays_per_wall_s = 0.0;
  double physics_step_us = 0.0;  // per physics step, sensors included
  sim::RayCasterBenchResult rays;
  LineExtractorBench lines;
};

// Runs a P3-DX with a 361-beam LMS 200 at 10 Hz and 16 sonars at 10 Hz, wall-following in
// `options.world` for `options.seconds` on one core; then times the ray casters on 200000 rays of
// that world and every line extractor on a fixed scan. The experiment is spelled in YAML like any
// other, so it exercises the real path. @throws sim::ConfigError for a bad world or duration.
BenchFigures RunBench(const BenchOptions& options);

}  // namespace plywood::eval
