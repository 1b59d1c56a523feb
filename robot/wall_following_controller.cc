#include "robot/wall_following_controller.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "robot/diff_drive_kinematics.h"

namespace plywood::robot {
namespace {

constexpr double kTimeSlackS = 1e-9;

// Folds a line direction into (-pi/2, pi/2]: a wall has no arrow, we take the one ahead.
double FoldLineAngle(double angle_rad) {
  double a = msgs::WrapAngle(angle_rad);
  if (a > std::numbers::pi / 2.0) a -= std::numbers::pi;
  if (a <= -std::numbers::pi / 2.0) a += std::numbers::pi;
  return a;
}

}  // namespace

std::string_view ToString(WallSide side) { return side == WallSide::kLeft ? "left" : "right"; }

std::string_view ToString(WallSensor sensor) {
  return sensor == WallSensor::kSonar ? "sonar" : "laser";
}

WallSide ParseWallSide(std::string_view text) {
  if (text == "left") return WallSide::kLeft;
  if (text == "right") return WallSide::kRight;
  throw std::invalid_argument("side: must be \"left\" or \"right\", got \"" + std::string(text) +
                              "\"");
}

WallSensor ParseWallSensor(std::string_view text) {
  if (text == "sonar") return WallSensor::kSonar;
  if (text == "laser") return WallSensor::kLaser;
  throw std::invalid_argument("sensor: must be \"sonar\" or \"laser\", got \"" + std::string(text) +
                              "\"");
}

void WallFollowingOptions::Validate() const {
  if (side != WallSide::kLeft && side != WallSide::kRight) {
    throw std::invalid_argument("side: must be left or right");
  }
  if (sensor != WallSensor::kSonar && sensor != WallSensor::kLaser) {
    throw std::invalid_argument("sensor: must be sonar or laser");
  }
  internal::RequirePositive("distance_m", distance_m);
  internal::RequirePositive("speed_m_s", speed_m_s);
  internal::RequirePositive("accel_m_s2", accel_m_s2);
  internal::RequirePositive("max_turn_rate_rad_s", max_turn_rate_rad_s);
  internal::RequirePositive("distance_gain_rad_per_m", distance_gain_rad_per_m);
  internal::RequirePositive("angle_gain_per_s", angle_gain_per_s);
  internal::RequirePositive("max_approach_angle_rad", max_approach_angle_rad);
  if (max_approach_angle_rad >= std::numbers::pi / 2.0) {
    throw std::invalid_argument("max_approach_angle_rad: must be < pi/2, got " +
                                std::to_string(max_approach_angle_rad));
  }
  internal::RequirePositive("side_window_rad", side_window_rad);
  internal::RequirePositive("front_window_rad", front_window_rad);
  internal::RequirePositive("max_wall_range_m", max_wall_range_m);
  if (max_wall_range_m <= distance_m) {
    throw std::invalid_argument("max_wall_range_m: must exceed distance_m, got " +
                                std::to_string(max_wall_range_m));
  }
  internal::RequirePositive("front_clearance_m", front_clearance_m);
  internal::RequireNonNegative("duration_s", duration_s);
}

WallFollowingController::WallFollowingController(const DiffDriveSpec& spec,
                                                 const WallFollowingOptions& options)
    : spec_(spec), options_(options), side_sign_(options.side == WallSide::kLeft ? 1.0 : -1.0) {
  spec_.Validate();
  options_.Validate();
}

void WallFollowingController::AddPoint(const msgs::Pose2D& X_RS, double beam_rad, double range_m,
                                       std::vector<Point>* side, std::vector<Point>* front) const {
  const msgs::Pose2D X_RP =
      X_RS * msgs::Pose2D{range_m * std::cos(beam_rad), range_m * std::sin(beam_rad), 0.0};
  const double direction_rad = msgs::WrapAngle(X_RS.theta_rad + beam_rad);
  const double from_side_normal_rad =
      msgs::WrapAngle(direction_rad - side_sign_ * std::numbers::pi / 2.0);
  if (std::abs(from_side_normal_rad) <= options_.side_window_rad &&
      range_m <= options_.max_wall_range_m) {
    side->push_back({X_RP.x_m, X_RP.y_m});
  }
  if (std::abs(direction_rad) <= options_.front_window_rad) front->push_back({X_RP.x_m, X_RP.y_m});
}

void WallFollowingController::CollectPoints(const ControllerInput& input, std::vector<Point>* side,
                                            std::vector<Point>* front) const {
  if (options_.sensor == WallSensor::kSonar) {
    for (const msgs::RangeReading& reading : input.sonar->readings) {
      if (!reading.echo || reading.range_m < input.sonar->range_min_m ||
          reading.range_m > input.sonar->range_max_m) {
        continue;
      }
      AddPoint(reading.X_RS, 0.0, reading.range_m, side, front);
    }
  } else {
    const msgs::LaserScan& scan = *input.laser;
    for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
      if (scan.IsReturn(i))
        AddPoint(scan.X_RS, scan.BeamAngleRad(i), scan.ranges_m[i], side, front);
    }
  }
}

std::optional<WallFollowingController::WallEstimate> WallFollowingController::FitWall(
    const std::vector<Point>& side, double theta_estimate_rad) {
  if (side.empty()) return std::nullopt;
  double cx = 0.0, cy = 0.0;
  for (const Point& p : side) {
    cx += p.x_m;
    cy += p.y_m;
  }
  cx /= side.size();
  cy /= side.size();
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
  for (const Point& p : side) {
    sxx += (p.x_m - cx) * (p.x_m - cx);
    syy += (p.y_m - cy) * (p.y_m - cy);
    sxy += (p.x_m - cx) * (p.y_m - cy);
  }
  double angle_rad = 0.0;
  if (sxx + syy > 1e-12) {
    // Principal axis of the scatter: the total-least-squares line direction.
    angle_rad = FoldLineAngle(0.5 * std::atan2(2.0 * sxy, sxx - syy));
    wall_heading_W_rad_ = theta_estimate_rad + angle_rad;
  } else if (wall_heading_W_rad_) {
    angle_rad = FoldLineAngle(*wall_heading_W_rad_ - theta_estimate_rad);
  }
  // Distance from the centre of rotation to the line through the centroid.
  const double distance_m = std::abs(cx * std::sin(angle_rad) - cy * std::cos(angle_rad));
  return WallEstimate{distance_m, angle_rad};
}

msgs::WheelSpeedCommand WallFollowingController::Update(const ControllerInput& input) {
  const double dt_s = last_time_s_ ? input.time_s - *last_time_s_ : 0.0;
  last_time_s_ = input.time_s;
  if (!start_time_s_) start_time_s_ = input.time_s;
  if (options_.duration_s > 0.0 &&
      input.time_s - *start_time_s_ >= options_.duration_s - kTimeSlackS) {
    finished_ = true;
  }
  const bool have_data =
      options_.sensor == WallSensor::kSonar ? input.sonar != nullptr : input.laser != nullptr;
  if (finished_ || !have_data) {
    speed_m_s_ = 0.0;
    turning_away_ = false;
    return {};
  }

  std::vector<Point> side, front;
  CollectPoints(input, &side, &front);
  wall_ = FitWall(side, input.X_WR_estimate.theta_rad);

  double ahead_m = std::numeric_limits<double>::infinity();
  for (const Point& p : front) {
    if (p.x_m > 0.0) ahead_m = std::min(ahead_m, p.x_m);
  }
  // Hysteresis: once blocked, keep turning until the way ahead is clear by a further distance_m
  // and the side sees a wall roughly parallel (or none), else the wall being left behind pulls the
  // robot straight back into the corner.
  if (ahead_m < options_.front_clearance_m) turning_away_ = true;
  if (turning_away_ && ahead_m > options_.front_clearance_m + options_.distance_m &&
      (!wall_ || std::abs(wall_->angle_rad) < options_.max_approach_angle_rad / 2.0)) {
    turning_away_ = false;
  }
  if (turning_away_) {
    speed_m_s_ = 0.0;
    return TwistToWheelSpeeds(spec_, {0.0, -side_sign_ * options_.max_turn_rate_rad_s});
  }

  speed_m_s_ =
      dt_s > 0.0 ? std::min(options_.speed_m_s, speed_m_s_ + options_.accel_m_s2 * dt_s) : 0.0;
  double yaw_rate_rad_s = 0.0;
  if (!wall_) {
    yaw_rate_rad_s = side_sign_ * speed_m_s_ / options_.distance_m;
  } else {
    const double distance_error_m = wall_->distance_m - options_.distance_m;
    // Heading relative to the wall is minus the wall's direction seen from the robot.
    const double heading_to_wall_rad = -wall_->angle_rad;
    const double heading_wanted_rad =
        side_sign_ * std::clamp(options_.distance_gain_rad_per_m * distance_error_m,
                                -options_.max_approach_angle_rad, options_.max_approach_angle_rad);
    yaw_rate_rad_s = options_.angle_gain_per_s * (heading_wanted_rad - heading_to_wall_rad);
  }
  yaw_rate_rad_s =
      std::clamp(yaw_rate_rad_s, -options_.max_turn_rate_rad_s, options_.max_turn_rate_rad_s);
  return TwistToWheelSpeeds(spec_, {speed_m_s_, yaw_rate_rad_s});
}

}  // namespace plywood::robot
