#pragma once

#include <vector>

#include "msgs/pose2d.h"

namespace plywood::robot {

// How far an estimated trajectory strayed from ground truth. The definitions are the project's
// contract (docs/metrics.md); every scorer calls this one implementation.
struct TrajectoryErrors {
  double final_error_m = 0.0;         // |p_est(T) - p_true(T)|
  double heading_error_deg = 0.0;     // wrap(theta_est(T) - theta_true(T)), signed
  double distance_travelled_m = 0.0;  // path length of the ground truth
  double drift_percent = 0.0;         // 100 * final_error_m / distance_travelled_m; NaN (no
                                      // number: JSON null) below kMinDriftDistanceM of travel
  double ate_rms_m = 0.0;             // RMS over samples of |p_est(t) - p_true(t)|, no alignment:
                                      // both start from the same known pose
};

// Drift as a percentage of the distance travelled is undefined for a robot that did not travel:
// below this path length (1 cm; wheel-contact jitter of a standing robot is micrometres) a ratio
// would be a division by zero or a meaningless huge number.
inline constexpr double kMinDriftDistanceM = 0.01;

// `truth` and `estimate` are sampled at the same instants. @pre equal, non-zero sizes.
TrajectoryErrors ScoreTrajectory(const std::vector<msgs::Pose2D>& truth,
                                 const std::vector<msgs::Pose2D>& estimate);

}  // namespace plywood::robot
