#include "robot/control/waypoint_controller.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace plywood::robot {

void WaypointOptions::Validate() const {
  if (waypoints.empty()) throw std::invalid_argument("waypoints: must hold at least one point");
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    if (!std::isfinite(waypoints[i].x_m) || !std::isfinite(waypoints[i].y_m)) {
      throw std::invalid_argument("waypoints: point " + std::to_string(i) + " is not finite");
    }
  }
  internal::RequirePositive("speed_m_s", speed_m_s);
  internal::RequirePositive("max_turn_rate_rad_s", max_turn_rate_rad_s);
  internal::RequirePositive("accel_m_s2", accel_m_s2);
  internal::RequirePositive("heading_gain_per_s", heading_gain_per_s);
  internal::RequirePositive("turn_in_place_above_rad", turn_in_place_above_rad);
  internal::RequirePositive("reach_tolerance_m", reach_tolerance_m);
}

WaypointController::WaypointController(const DiffDriveSpec& spec, const WaypointOptions& options)
    : spec_(spec), options_(options) {
  spec_.Validate();
  options_.Validate();
  internal::RequireDrivableSpeed(spec_, "speed_m_s", options_.speed_m_s);
}

msgs::WheelSpeedCommand WaypointController::Update(const ControllerInput& input) {
  const double dt_s = last_time_s_ ? input.time_s - *last_time_s_ : 0.0;
  last_time_s_ = input.time_s;
  if (finished_) return {};
  const msgs::Pose2D& X_WR = input.X_WR_estimate;

  auto is_last = [&] { return !options_.loop && target_ + 1 == options_.waypoints.size(); };
  double dx = 0.0, dy = 0.0, distance_m = 0.0;
  // Several waypoints may be within reach at once (a dense list): pass all of them this tick.
  for (std::size_t passed = 0; passed <= options_.waypoints.size(); ++passed) {
    const Waypoint& target = options_.waypoints[target_];
    dx = target.x_m - X_WR.x_m;
    dy = target.y_m - X_WR.y_m;
    distance_m = std::hypot(dx, dy);
    if (distance_m > options_.reach_tolerance_m) break;
    // The last waypoint is reached only once the robot can stop within one tick, so it finishes
    // at rest instead of dropping from speed to zero at the edge of the tolerance.
    if (is_last() && speed_m_s_ > options_.accel_m_s2 * dt_s) break;
    ++reached_;
    if (target_ + 1 < options_.waypoints.size()) {
      ++target_;
    } else if (options_.loop) {
      target_ = 0;
    } else {
      finished_ = true;
      speed_m_s_ = 0.0;
      return {};
    }
  }

  const double bearing_error_rad = msgs::WrapAngle(std::atan2(dy, dx) - X_WR.theta_rad);
  if (std::abs(bearing_error_rad) > options_.turn_in_place_above_rad) turning_in_place_ = true;
  if (std::abs(bearing_error_rad) < options_.turn_in_place_above_rad / 2.0) {
    turning_in_place_ = false;
  }
  const double yaw_rate_rad_s =
      std::clamp(options_.heading_gain_per_s * bearing_error_rad, -options_.max_turn_rate_rad_s,
                 options_.max_turn_rate_rad_s);
  if (turning_in_place_) {
    speed_m_s_ = 0.0;
    return TwistToWheelSpeeds(spec_, {0.0, yaw_rate_rad_s});
  }
  if (is_last()) {
    // Brake towards the waypoint itself; StoppingSpeed's last step lands on it.
    speed_m_s_ = StoppingSpeed(speed_m_s_, options_.speed_m_s, options_.accel_m_s2, distance_m,
                               0.1 * options_.reach_tolerance_m, dt_s);
  } else {
    // Intermediate waypoints are driven through at cruise speed.
    speed_m_s_ =
        dt_s > 0.0 ? std::min(options_.speed_m_s, speed_m_s_ + options_.accel_m_s2 * dt_s) : 0.0;
  }
  const double forward_m_s = speed_m_s_ * std::max(0.0, std::cos(bearing_error_rad));
  return TwistToWheelSpeeds(spec_, {forward_m_s, yaw_rate_rad_s});
}

}  // namespace plywood::robot
