#include "robot/control/square_path_controller.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"
#include "robot/control/tick_time_slack.h"

namespace plywood::robot {

std::string_view ToString(SquareDirection direction) {
  return direction == SquareDirection::kClockwise ? "cw" : "ccw";
}

SquareDirection ParseSquareDirection(std::string_view text) {
  if (text == "cw") return SquareDirection::kClockwise;
  if (text == "ccw") return SquareDirection::kCounterClockwise;
  throw std::invalid_argument("direction: must be \"cw\" or \"ccw\", got \"" + std::string(text) +
                              "\"");
}

void SquarePathOptions::Validate() const {
  internal::RequirePositive("side_m", side_m);
  if (direction != SquareDirection::kClockwise && direction != SquareDirection::kCounterClockwise) {
    throw std::invalid_argument("direction: must be cw or ccw");
  }
  // Every lap's moves are laid out up front (16 per lap): 1e9 laps overflowed 4 * laps (UBSan),
  // 1e8 would ask for gigabytes. 10000 laps of the smallest square outlast any run.
  if (laps < 1 || laps > kMaxSquareLaps) {
    throw std::invalid_argument("laps: must be in [1, " + std::to_string(kMaxSquareLaps) +
                                "], got " + std::to_string(laps));
  }
  internal::RequirePositive("speed_m_s", speed_m_s);
  internal::RequirePositive("turn_rate_rad_s", turn_rate_rad_s);
  internal::RequirePositive("accel_m_s2", accel_m_s2);
  internal::RequireNonNegative("dwell_s", dwell_s);
  internal::RequireNonNegative("heading_gain_per_s", heading_gain_per_s);
  internal::RequireNonNegative("cross_track_gain_rad_per_m", cross_track_gain_rad_per_m);
  internal::RequirePositive("position_tolerance_m", position_tolerance_m);
  internal::RequirePositive("heading_tolerance_rad", heading_tolerance_rad);
}

SquarePathController::SquarePathController(const DiffDriveSpec& spec,
                                           const SquarePathOptions& options)
    : spec_(spec), options_(options) {
  spec_.Validate();
  options_.Validate();
  const double max_rim_m_s = spec_.max_wheel_speed_rad_s * spec_.wheel_radius_m;
  if (options_.speed_m_s > max_rim_m_s) {
    throw std::invalid_argument("speed_m_s: " + msgs::ShortestNumber(options_.speed_m_s) +
                                " needs more than max_wheel_speed_rad_s allows (" +
                                msgs::SixDigitNumber(max_rim_m_s) + " m/s)");
  }
  if (options_.turn_rate_rad_s * spec_.track_m / 2.0 > max_rim_m_s) {
    throw std::invalid_argument(
        "turn_rate_rad_s: " + msgs::ShortestNumber(options_.turn_rate_rad_s) +
        " needs more than max_wheel_speed_rad_s allows (" +
        msgs::SixDigitNumber(2.0 * max_rim_m_s / spec_.track_m) + " rad/s)");
  }
}

std::vector<msgs::Pose2D> SquareCorners(const msgs::Pose2D& X_WR_start,
                                        const SquarePathOptions& options) {
  // Corner k in the start frame: (0,0), (side,0), (side,±side), (0,±side), with the heading of the
  // leg leaving it. Headings come from the corner index, not from accumulating turns, so nothing
  // drifts over laps.
  const double sign = options.direction == SquareDirection::kCounterClockwise ? 1.0 : -1.0;
  static constexpr int kX[4] = {0, 1, 1, 0};
  static constexpr int kY[4] = {0, 0, 1, 1};
  std::vector<msgs::Pose2D> corners;
  for (int k = 0; k < 4; ++k) {
    const msgs::Pose2D X_SC{kX[k] * options.side_m, sign * kY[k] * options.side_m,
                            msgs::WrapAngle(sign * k * std::numbers::pi / 2.0)};
    corners.push_back(X_WR_start * X_SC);
  }
  return corners;
}

void SquarePathController::Plan(const msgs::Pose2D& X_WR_start) {
  corners_ = SquareCorners(X_WR_start, options_);

  moves_.clear();
  const int legs = 4 * options_.laps;
  for (int leg = 0; leg < legs; ++leg) {
    const msgs::Pose2D& from = corners_[leg % 4];
    const msgs::Pose2D& to = corners_[(leg + 1) % 4];
    moves_.push_back({Move::Kind::kStraight, from, to});
    moves_.push_back({Move::Kind::kDwell, {}, {}});
    if (leg + 1 < legs || options_.final_turn) {
      moves_.push_back({Move::Kind::kTurn, {}, to});
      moves_.push_back({Move::Kind::kDwell, {}, {}});
    }
  }
}

void SquarePathController::Advance(double time_s) {
  ++move_index_;
  move_start_s_ = time_s;
  speed_ = 0.0;
  turn_sign_ = 0.0;
}

std::optional<BodyTwist> SquarePathController::Step(const Move& move, const ControllerInput& input,
                                                    double dt_s) {
  const msgs::Pose2D& X_WR = input.X_WR_estimate;
  switch (move.kind) {
    case Move::Kind::kDwell:
      if (input.time_s - move_start_s_ >= options_.dwell_s - kTickTimeSlackS) return std::nullopt;
      return BodyTwist{};
    case Move::Kind::kStraight: {
      const double ux = std::cos(move.from.theta_rad), uy = std::sin(move.from.theta_rad);
      // Distance still to go along the leg, and signed offset to the left of the leg's line.
      const double remaining_m = (move.to.x_m - X_WR.x_m) * ux + (move.to.y_m - X_WR.y_m) * uy;
      const double offset_m = ux * (X_WR.y_m - move.from.y_m) - uy * (X_WR.x_m - move.from.x_m);
      if (remaining_m <= options_.position_tolerance_m) return std::nullopt;
      speed_ = StoppingSpeed(speed_, options_.speed_m_s, options_.accel_m_s2, remaining_m,
                             options_.position_tolerance_m, dt_s);
      const double heading_wanted_rad =
          move.from.theta_rad - std::atan(options_.cross_track_gain_rad_per_m * offset_m);
      const double yaw_rate_rad_s = std::clamp(
          options_.heading_gain_per_s * msgs::WrapAngle(heading_wanted_rad - X_WR.theta_rad),
          -options_.turn_rate_rad_s, options_.turn_rate_rad_s);
      return BodyTwist{speed_, yaw_rate_rad_s};
    }
    case Move::Kind::kTurn: {
      const double error_rad = msgs::WrapAngle(move.to.theta_rad - X_WR.theta_rad);
      if (turn_sign_ == 0.0) turn_sign_ = error_rad >= 0.0 ? 1.0 : -1.0;
      // Done within tolerance, or once past the target (a noisy estimate must not make the robot
      // hunt back and forth forever).
      if (std::abs(error_rad) <= options_.heading_tolerance_rad || error_rad * turn_sign_ < 0.0) {
        return std::nullopt;
      }
      const double angular_accel_rad_s2 = options_.accel_m_s2 / (spec_.track_m / 2.0);
      speed_ = StoppingSpeed(speed_, options_.turn_rate_rad_s, angular_accel_rad_s2,
                             std::abs(error_rad), options_.heading_tolerance_rad, dt_s);
      return BodyTwist{0.0, turn_sign_ * speed_};
    }
  }
  return std::nullopt;
}

msgs::WheelSpeedCommand SquarePathController::Update(const ControllerInput& input) {
  if (moves_.empty()) {
    Plan(input.X_WR_estimate);
    move_start_s_ = input.time_s;
  }
  const double dt_s = last_time_s_ ? input.time_s - *last_time_s_ : 0.0;
  last_time_s_ = input.time_s;
  while (move_index_ < moves_.size()) {
    if (const auto twist = Step(moves_[move_index_], input, dt_s)) {
      return TwistToWheelSpeeds(spec_, *twist);
    }
    Advance(input.time_s);
  }
  return {};
}

bool SquarePathController::Finished() const {
  return !moves_.empty() && move_index_ >= moves_.size();
}

}  // namespace plywood::robot
