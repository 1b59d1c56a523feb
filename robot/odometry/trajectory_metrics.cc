#include "robot/odometry/trajectory_metrics.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace plywood::robot {

TrajectoryErrors ScoreTrajectory(const std::vector<msgs::Pose2D>& truth,
                                 const std::vector<msgs::Pose2D>& estimate) {
  if (truth.empty() || truth.size() != estimate.size()) {
    throw std::invalid_argument("ScoreTrajectory: trajectories must be non-empty and equally long");
  }
  TrajectoryErrors errors;
  double sum_squared = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const double dx = estimate[i].x_m - truth[i].x_m, dy = estimate[i].y_m - truth[i].y_m;
    sum_squared += dx * dx + dy * dy;
    if (i > 0) {
      errors.distance_travelled_m +=
          std::hypot(truth[i].x_m - truth[i - 1].x_m, truth[i].y_m - truth[i - 1].y_m);
    }
  }
  const msgs::Pose2D& t = truth.back();
  const msgs::Pose2D& e = estimate.back();
  errors.final_error_m = std::hypot(e.x_m - t.x_m, e.y_m - t.y_m);
  errors.heading_error_deg = msgs::WrapAngle(e.theta_rad - t.theta_rad) * 180.0 / std::numbers::pi;
  errors.drift_percent = errors.distance_travelled_m >= kMinDriftDistanceM
                             ? 100.0 * errors.final_error_m / errors.distance_travelled_m
                             : std::numeric_limits<double>::quiet_NaN();
  errors.ate_rms_m = std::sqrt(sum_squared / static_cast<double>(truth.size()));
  return errors;
}

}  // namespace plywood::robot
