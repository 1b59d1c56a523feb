#include "robot/drive/diff_drive_kinematics.h"

#include <algorithm>
#include <cmath>

namespace plywood::robot {

BodyTwist WheelSpeedsToTwist(const DiffDriveSpec& spec, const msgs::WheelSpeedCommand& wheels) {
  const double r = spec.wheel_radius_m;
  return {r * (wheels.left_rad_s + wheels.right_rad_s) / 2.0,
          r * (wheels.right_rad_s - wheels.left_rad_s) / spec.track_m};
}

msgs::WheelSpeedCommand TwistToWheelSpeeds(const DiffDriveSpec& spec, const BodyTwist& twist) {
  const double half_track = spec.track_m / 2.0;
  msgs::WheelSpeedCommand wheels{
      (twist.linear_m_s - twist.angular_rad_s * half_track) / spec.wheel_radius_m,
      (twist.linear_m_s + twist.angular_rad_s * half_track) / spec.wheel_radius_m};
  const double fastest = std::max(std::abs(wheels.left_rad_s), std::abs(wheels.right_rad_s));
  if (fastest > spec.max_wheel_speed_rad_s) {
    const double scale = spec.max_wheel_speed_rad_s / fastest;
    wheels.left_rad_s *= scale;
    wheels.right_rad_s *= scale;
  }
  return wheels;
}

msgs::Pose2D IntegrateMidpoint(const msgs::Pose2D& X_WR, double ds_m, double dtheta_rad) {
  const double heading = X_WR.theta_rad + dtheta_rad / 2.0;
  return {X_WR.x_m + ds_m * std::cos(heading), X_WR.y_m + ds_m * std::sin(heading),
          msgs::WrapAngle(X_WR.theta_rad + dtheta_rad)};
}

msgs::Pose2D IntegrateArc(const msgs::Pose2D& X_WR, double ds_m, double dtheta_rad) {
  // The chord of an arc of length ds turning dtheta has length ds * sinc(dtheta/2) and points along
  // the mid heading, so the midpoint rule is exact up to that factor.
  const double half = dtheta_rad / 2.0;
  const double chord = std::abs(half) < 1e-9 ? ds_m : ds_m * std::sin(half) / half;
  return IntegrateMidpoint(X_WR, chord, dtheta_rad);
}

}  // namespace plywood::robot
