#include "eval/odometry/weighted_gain_protocol.h"

#include <cmath>
#include <cstddef>
#include <cstdio>

#include "msgs/shortest_number.h"
#include "robot/calibration/weighted_gain_search.h"
#include "robot/odometry/odometry_increments.h"
#include "robot/odometry/trajectory_metrics.h"
#include "sim/config/config_archive.h"
#include "sim/config/config_error.h"
#include "sim/config/experiment_config.h"
#include "sim/config/yaml_fields.h"
#include "sim/runner/experiment_runner.h"
#include "sim/runner/run_writer.h"

namespace plywood::robot {

template <typename A>
void VisitFields(A& a, GainGridOptions& o) {
  a("min_gain", o.min_gain);
  a("max_gain", o.max_gain);
  a("step", o.step);
}

}  // namespace plywood::robot

namespace plywood::eval {

namespace {

// @throws sim::ConfigError naming the field.
robot::GainGridOptions ReadGainGrid(const sim::ExperimentConfig& config) {
  robot::GainGridOptions grid;
  sim::ReadOptions(
      sim::YamlFields(config.protocol_options, config.source_file, "weighted_gain_search"), grid);
  return grid;
}

}  // namespace

void CheckWeightedGainOptions(const sim::ExperimentConfig& config) { ReadGainGrid(config); }

int WeightedGainProtocol(const ProtocolContext& context) {
  const sim::ExperimentConfig& config = context.config;
  const robot::GainGridOptions grid = ReadGainGrid(config);
  const robot::OdometryGeometry geometry =
      robot::CalibratedGeometry(config.nominal, config.odometry.calibration);

  sim::ExperimentRunner runner(config);
  runner.Run();
  const sim::RunRecord& record = runner.record();
  if (record.encoders.empty() || record.gyro.empty() || record.trajectory.empty()) {
    throw sim::ConfigError(config.source_file, "sensors",
                           "weighted_gain_search needs sensors.encoders and sensors.gyro");
  }
  robot::GainCalibrationRun run;
  run.encoders = record.encoders;
  run.gyro = record.gyro;
  run.X_WR_initial = record.trajectory.front().truth;
  run.X_WR_final = record.trajectory.back().truth;
  run.distance_m = 0.0;
  for (std::size_t i = 1; i < record.trajectory.size(); ++i) {
    const msgs::Pose2D& a = record.trajectory[i - 1].truth;
    const msgs::Pose2D& b = record.trajectory[i].truth;
    run.distance_m += std::hypot(b.x_m - a.x_m, b.y_m - a.y_m);
  }
  // The search minimises drift_percent, which is undefined below 1 cm of travel: refused naming
  // the experiment, not as the search's own "run: distance_m" (s63).
  if (!(run.distance_m >= robot::kMinDriftDistanceM)) {
    throw sim::ConfigError(
        config.source_file, "weighted_gain_search",
        "the robot travelled " + msgs::ShortestNumber(run.distance_m) +
            " m in the run (duration_s = " + msgs::ShortestNumber(config.duration_s) +
            " s), less than 1 cm: drift_percent, which the search minimises, is undefined; give a "
            "run that travels (a longer duration_s, a controller that moves)");
  }
  const robot::GainSearchResult result =
      robot::SearchWeightedGains(geometry, config.odometry.weighted, grid, run);

  sim::RunRecord& out = runner.mutable_record();
  out.metrics.Set("weighted_gain_search.encoder_gain", result.encoder_gain);
  out.metrics.Set("weighted_gain_search.gyro_gain", result.gyro_gain);
  out.metrics.Set("weighted_gain_search.drift_percent", result.drift_percent);
  out.metrics.Set("weighted_gain_search.unit_drift_percent", result.unit_drift_percent);
  out.metrics.Set("weighted_gain_search.grid_points", static_cast<double>(result.evaluated));
  sim::WriteRunOutputs(config, out, context.out_dir);
  if (!context.quiet) {
    std::printf("%-34s %s, %d gain pairs in [%.3f, %.3f] step %.4f\n", "weighted gain search",
                config.name.c_str(), result.evaluated, grid.min_gain, grid.max_gain, grid.step);
  }
  // The result is the point of the command: print it even with --quiet.
  std::printf("%-34s encoder_gain %.4f, gyro_gain %.4f: drift %.3f %% (gains 1/1: %.3f %%)\n",
              "best gains", result.encoder_gain, result.gyro_gain, result.drift_percent,
              result.unit_drift_percent);
  return 0;
}

}  // namespace plywood::eval
