#include "msgs/pose2d.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"

namespace plywood::msgs {

double WrapAngle(double angle_rad) {
  // Within two turns of 0 (nearly every call: line fits, pose products) the remainder below is
  // angle_rad itself or angle_rad -+ 2 pi, which Sterbenz's lemma makes exact: the same bits
  // without the std::remainder call. Both edges as below: pi stays, -pi becomes pi.
  constexpr double kPi = std::numbers::pi;
  if (angle_rad > -kPi && angle_rad <= kPi) return angle_rad;
  if (angle_rad > kPi && angle_rad < 2.0 * kPi) return angle_rad - 2.0 * kPi;
  if (angle_rad > -2.0 * kPi && angle_rad <= -kPi) return angle_rad + 2.0 * kPi;
  double wrapped = std::remainder(angle_rad, 2.0 * std::numbers::pi);
  if (wrapped <= -std::numbers::pi) wrapped += 2.0 * std::numbers::pi;
  return wrapped;
}

Pose2D Pose2D::operator*(const Pose2D& X_BC) const {
  const double c = std::cos(theta_rad), s = std::sin(theta_rad);
  return {x_m + c * X_BC.x_m - s * X_BC.y_m, y_m + s * X_BC.x_m + c * X_BC.y_m,
          WrapAngle(theta_rad + X_BC.theta_rad)};
}

Pose2D Pose2D::Inverse() const {
  const double c = std::cos(theta_rad), s = std::sin(theta_rad);
  return {-c * x_m - s * y_m, s * x_m - c * y_m, WrapAngle(-theta_rad)};
}

void RequireFinitePose(const char* field, const Pose2D& pose) {
  if (!std::isfinite(pose.x_m) || !std::isfinite(pose.y_m) || !std::isfinite(pose.theta_rad)) {
    throw std::invalid_argument(std::string(field) + ": must be finite, got (" +
                                ShortestNumber(pose.x_m) + ", " + ShortestNumber(pose.y_m) + ", " +
                                ShortestNumber(pose.theta_rad) + ")");
  }
}

}  // namespace plywood::msgs
