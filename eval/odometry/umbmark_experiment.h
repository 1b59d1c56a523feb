#pragma once

#include <functional>
#include <string>
#include <vector>

#include "robot/calibration/turn_calibration.h"
#include "robot/calibration/umbmark.h"
#include "robot/odometry/odometry_increments.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"
#include "sim/runner/metrics.h"

namespace plywood::sim {
class YamlFields;
}  // namespace plywood::sim

namespace plywood::eval {

// The `umbmark:` section of an experiment with `protocol: umbmark`.
struct UmbmarkOptions {
  int runs_per_direction = 5;  // Borenstein & Feng: 5 clockwise + 5 counter-clockwise
  bool correct = true;         // apply the correction and drive the benchmark again
  bool write_runs = true;      // each run's outputs in before/cw_1 ... after/ccw_5

  // @throws std::invalid_argument naming the offending field.
  void Validate() const;
};

template <typename A>
void VisitFields(A& a, UmbmarkOptions& o) {
  a("runs_per_direction", o.runs_per_direction);
  a("correct", o.correct);
  a("write_runs", o.write_runs);
}

// @throws sim::ConfigError naming the field.
UmbmarkOptions ReadUmbmarkOptions(const sim::ExperimentConfig& config);

// One benchmark (n squares each way) driven with one odometry calibration.
struct UmbmarkStage {
  robot::OdometryCalibration calibration;  // what the odometry used
  std::vector<robot::UmbmarkRun> runs;
  robot::UmbmarkResult result;
  // Seed 001's calibration from the same runs: every on-the-spot turn, odometry vs truth.
  std::vector<robot::TurnObservation> turns;
  robot::TurnCalibration turn_calibration;
};

struct UmbmarkOutcome {
  UmbmarkStage before;
  UmbmarkStage after;  // empty runs when !options.correct
  robot::OdometryCalibration corrected;
  sim::Metrics metrics;  // umbmark.*
};

// Called after each run with its stage ("before"/"after"), name ("cw_1"...), config and record.
using UmbmarkRunSink =
    std::function<void(const std::string& stage, const std::string& name,
                       const sim::ExperimentConfig& config, const sim::RunRecord& record)>;

// Runs UMBmark on `config`: a square_path controller steered by an odometry estimator
// (controller.steer_by, which must not be ground_truth). The configured spawn is the start corner
// facing along the counter-clockwise square's first leg; clockwise runs start at the same corner
// turned 90 deg left, so both directions drive the same square. Each square (cw_1, ccw_2, ...)
// draws its noise from its own stream of config.seed (sim::ComponentSeed), the same in both
// stages, so the runs differ in their noise, no two seeds share a square's noise, and the whole
// protocol is reproducible.
// @throws sim::ConfigError when the config cannot drive UMBmark.
UmbmarkOutcome RunUmbmark(const sim::ExperimentConfig& config, const UmbmarkOptions& options,
                          const UmbmarkRunSink& sink = {});

// The on-the-spot turns of a run, found from the estimate `estimator` in the trajectory: motions
// between two rests that turn more than 45 deg while moving less than 5 cm. A rest is a sample
// whose estimate is that of the sample at least `estimate_period_s` (the period at which the
// estimate is updated: the encoders') before it, or of the sample before it when that is further
// back: at a trajectory rate above the encoders' the estimate stands still between their reads
// while the robot turns.
std::vector<robot::TurnObservation> ExtractTurns(const sim::RunRecord& record,
                                                 std::size_t estimator,
                                                 double estimate_period_s = 0.0);

}  // namespace plywood::eval
