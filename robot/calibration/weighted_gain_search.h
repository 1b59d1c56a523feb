#pragma once

#include <vector>

#include "msgs/gyro_rate.h"
#include "msgs/pose2d.h"
#include "msgs/wheel_encoders.h"
#include "robot/odometry/odometry_increments.h"
#include "robot/odometry/weighted_fused_odometry.h"

namespace plywood::robot {

// The square grid of per-sensor gains tried for seed 004 eq. 5: every (encoder_gain, gyro_gain)
// in {min_gain, min_gain + step, ..., max_gain}^2.
struct GainGridOptions {
  double min_gain = 0.9;
  double max_gain = 1.1;
  double step = 0.005;

  // @throws std::invalid_argument naming the offending field.
  void Validate() const;
};

// A recorded calibration run: the sensor messages in the order they arrived and the ground truth
// the gains are scored against.
struct GainCalibrationRun {
  std::vector<msgs::WheelEncoders> encoders;
  std::vector<msgs::GyroRate> gyro;
  msgs::Pose2D X_WR_initial;  // where every estimate starts (the true start pose)
  msgs::Pose2D X_WR_final;    // true end pose
  double distance_m = 0.0;    // true path length, > 0
};

struct GainSearchResult {
  double encoder_gain = 1.0;
  double gyro_gain = 1.0;
  double drift_percent = 0.0;       // at the best gains
  double unit_drift_percent = 0.0;  // at gains 1/1 (eq. 4), for comparison
  int evaluated = 0;                // grid points replayed
};

// Final position error / distance (%) of WeightedFusedOdometry with `options` replayed over `run`:
// messages merged by time, encoders before gyro at equal stamps (as the runner feeds them).
double ReplayDrift(const OdometryGeometry& geometry, const WeightedFusedOdometryOptions& options,
                   const GainCalibrationRun& run);

// Seed 004's grid search: the gains (other options from `base`) with the lowest drift on `run`;
// ties keep the point closest to 1/1. Score on a calibration run, never on the runs that are then
// evaluated: one run leaves a line of equally good pairs (c_enco s_enc + c_gyro s_gyro = 2 for
// heading scale errors s), and the grid picks the pair that also cancels this run's noise.
// @throws std::invalid_argument on a bad grid, or a run without messages or distance.
GainSearchResult SearchWeightedGains(const OdometryGeometry& geometry,
                                     const WeightedFusedOdometryOptions& base,
                                     const GainGridOptions& grid, const GainCalibrationRun& run);

}  // namespace plywood::robot
