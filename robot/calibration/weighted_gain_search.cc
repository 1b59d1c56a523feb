#include "robot/calibration/weighted_gain_search.h"

#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"
#include "robot/odometry/odometry_gain.h"
#include "robot/odometry/trajectory_metrics.h"

namespace plywood::robot {
void GainGridOptions::Validate() const {
  // The grid's gains are the weighted estimator's own (odometry.weighted takes [0.5, 2]): one
  // outside failed the first replay, after the whole run, as "encoder_gain: must be ..." without
  // the file or this section's field (s49).
  internal::RequireGain("min_gain", min_gain);
  if (!(max_gain >= min_gain)) {
    throw std::invalid_argument("max_gain: must be finite and >= min_gain, got " +
                                msgs::ShortestNumber(max_gain));
  }
  internal::RequireGain("max_gain", max_gain);
  if (!(step > 0.0) || !std::isfinite(step)) {
    throw std::invalid_argument("step: must be finite and > 0, got " + msgs::ShortestNumber(step));
  }
  const double steps = (max_gain - min_gain) / step;
  if (steps > 2000.0) {
    throw std::invalid_argument("step: more than 2000 grid points per axis, got " +
                                msgs::ShortestNumber(step));
  }
  // The grid runs from min_gain to max_gain: a step that does not divide the range stopped short
  // of max_gain, and one beyond the range tried min_gain alone and reported it as the best gains,
  // drift 12.45 % beside 1.34 % at 1 / 1 (s49). 1e-9: the slack SearchWeightedGains counts with.
  if (std::abs(steps - std::round(steps)) > 1e-9) {
    const double last = min_gain + std::floor(steps) * step;
    throw std::invalid_argument(
        "step: " + msgs::ShortestNumber(step) + " does not divide max_gain - min_gain = " +
        msgs::SixDigitNumber(max_gain - min_gain) + " (" + msgs::SixDigitNumber(steps) +
        " steps): the grid would end at " + msgs::SixDigitNumber(last) + ", short of max_gain " +
        msgs::ShortestNumber(max_gain) + "; give a step that divides it");
  }
}

double ReplayDrift(const OdometryGeometry& geometry, const WeightedFusedOdometryOptions& options,
                   const GainCalibrationRun& run) {
  WeightedFusedOdometry odometry(geometry, options, run.X_WR_initial);
  std::size_t g = 0;
  for (const msgs::WheelEncoders& e : run.encoders) {
    while (g < run.gyro.size() && run.gyro[g].time_s < e.time_s) odometry.AddGyro(run.gyro[g++]);
    odometry.AddEncoders(e);
  }
  while (g < run.gyro.size()) odometry.AddGyro(run.gyro[g++]);
  const msgs::Pose2D X_WR = odometry.pose();
  return 100.0 * std::hypot(X_WR.x_m - run.X_WR_final.x_m, X_WR.y_m - run.X_WR_final.y_m) /
         run.distance_m;
}

GainSearchResult SearchWeightedGains(const OdometryGeometry& geometry,
                                     const WeightedFusedOdometryOptions& base,
                                     const GainGridOptions& grid, const GainCalibrationRun& run) {
  grid.Validate();
  base.Validate();
  if (run.encoders.empty() || run.gyro.empty()) {
    throw std::invalid_argument("run: needs encoder and gyro messages");
  }
  if (!(run.distance_m >= kMinDriftDistanceM)) {
    throw std::invalid_argument("run: distance_m: drift is undefined below 1 cm of travel, got " +
                                msgs::ShortestNumber(run.distance_m) + " m");
  }
  const int n =
      static_cast<int>(std::floor((grid.max_gain - grid.min_gain) / grid.step + 1e-9)) + 1;
  GainSearchResult result;
  WeightedFusedOdometryOptions options = base;
  options.encoder_gain = options.gyro_gain = 1.0;
  result.unit_drift_percent = ReplayDrift(geometry, options, run);
  double best = std::numeric_limits<double>::infinity();
  double best_distance_to_unit = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      options.encoder_gain = grid.min_gain + i * grid.step;
      options.gyro_gain = grid.min_gain + j * grid.step;
      const double drift = ReplayDrift(geometry, options, run);
      ++result.evaluated;
      const double to_unit = std::hypot(options.encoder_gain - 1.0, options.gyro_gain - 1.0);
      if (drift < best || (drift == best && to_unit < best_distance_to_unit)) {
        best = drift;
        best_distance_to_unit = to_unit;
        result.encoder_gain = options.encoder_gain;
        result.gyro_gain = options.gyro_gain;
      }
    }
  }
  result.drift_percent = best;
  return result;
}

}  // namespace plywood::robot
