#include "robot/calibration/turn_calibration.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace plywood::robot {

TurnCalibration CalibrateTurns(const std::vector<TurnObservation>& turns) {
  if (turns.empty()) throw std::invalid_argument("turn calibration needs at least one turn");
  constexpr double kRadToDeg = 180.0 / std::numbers::pi;
  TurnCalibration c;
  c.turns = static_cast<int>(turns.size());
  double sum_odometry = 0.0, sum_true = 0.0, sum_error = 0.0, sum_error2 = 0.0;
  for (const TurnObservation& t : turns) {
    if (t.odometry_turn_rad == 0.0 || t.true_turn_rad == 0.0) {
      throw std::invalid_argument("turn calibration: a turn of zero");
    }
    const double error_deg =
        (std::abs(t.true_turn_rad) - std::abs(t.odometry_turn_rad)) * kRadToDeg;
    sum_error += error_deg;
    sum_error2 += error_deg * error_deg;
    sum_odometry += std::abs(t.odometry_turn_rad);
    sum_true += std::abs(t.true_turn_rad);
  }
  const double n = static_cast<double>(turns.size());
  c.mean_error_deg = sum_error / n;
  c.error_sigma_deg =
      n > 1 ? std::sqrt(
                  std::max(0.0, (sum_error2 - n * c.mean_error_deg * c.mean_error_deg) / (n - 1)))
            : 0.0;
  c.track_ratio = sum_odometry / sum_true;
  // The robot turns sum_true for every sum_odometry asked of it.
  c.command_scale = sum_odometry / sum_true;
  return c;
}

}  // namespace plywood::robot
