#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "eval/lines/line_bench.h"
#include "sim/raycast/ray_caster_bench.h"
#include "sim/runner/experiment_runner.h"
#include "sim/runner/part_timer.h"

namespace plywood::eval {

struct BenchOptions {
  double seconds = 120.0;                   // simulated seconds of one wall-following run
  std::string world = "worlds/office.xml";  // MJCF room of the itemised run
  int repeats = 3;                          // repetitions per figure; the fastest is reported
  double min_wall_s = 1.0;                  // each repetition runs again until this much wall time
};

// One world's real-time factor: the fastest of the repetitions.
struct WorldSpeed {
  std::string label;
  int geoms = 0;             // geoms in the model, robot and floor included
  sim::RunCost cost;         // summed over the fastest repetition's runs
  sim::StepPartTimes parts;  // of that repetition, summed over its runs
};

// What `plywood bench` measured: wall-clock figures, so they differ from run to run.
struct BenchFigures {
  std::filesystem::path world;  // the resolved world of the itemised run
  WorldSpeed itemised;          // options.world, with per-part costs
  // hall, office, 3 x 3 tiled office, then both offices again in the planar drive
  std::vector<WorldSpeed> worlds;
  sim::RayCasterBenchResult rays;
  LineExtractorBench lines;
  // experiments/default.yaml through the plain run protocol, outputs and snapshot included.
  double default_run_wall_s = 0.0;
  double default_run_simulated_s = 0.0;
  // The same experiment's simulation alone (ExperimentRunner::Run: no outputs, no snapshot).
  double default_run_simulation_wall_s = 0.0;
  // Both default-run figures are the fastest of this many repetitions: at least options.repeats,
  // more until each figure's repetitions add up to options.min_wall_s of wall time.
  int default_run_repeats = 0;
};

// Runs a P3-DX with a 361-beam LMS 200 at 10 Hz and 16 sonars at 10 Hz, wall-following on one
// core: in `options.world` with every part of the step loop timed, then (untimed parts) in the
// hall, the office and a 3 x 3 tiled office; each figure is the fastest of `options.repeats`
// repetitions of at least `options.min_wall_s` of wall time. Then times the ray casters on 200000
// rays of that world, every line extractor on a fixed scan, and one `plywood run` of the default
// experiment into a temporary directory. The experiments are spelled in YAML like any other, so
// they exercise the real path. @throws sim::ConfigError for a bad world or duration.
BenchFigures RunBench(const BenchOptions& options);

}  // namespace plywood::eval
