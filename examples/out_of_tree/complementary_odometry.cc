#include "complementary_odometry.h"

#include <cmath>
#include <numbers>

namespace lab {

void ComplementaryOdometry::AddGyro(const plywood::msgs::GyroRate& gyro) {
  // Each sample is the mean rate since the previous one.
  if (previous_gyro_s_) gyro_angle_rad_ += gyro.yaw_rate_rad_s * (gyro.time_s - *previous_gyro_s_);
  previous_gyro_s_ = gyro.time_s;
  gyro_seen_ = true;
}

void ComplementaryOdometry::AddEncoders(const plywood::msgs::WheelEncoders& encoders) {
  if (!previous_encoders_) {
    previous_encoders_ = encoders;
    gyro_angle_rad_ = 0.0;
    return;
  }
  const double radians_per_tick = 2.0 * std::numbers::pi / geometry_.ticks_per_rev;
  const double left_m = static_cast<double>(encoders.left_ticks - previous_encoders_->left_ticks) *
                        radians_per_tick * geometry_.left_wheel_radius_m;
  const double right_m =
      static_cast<double>(encoders.right_ticks - previous_encoders_->right_ticks) *
      radians_per_tick * geometry_.right_wheel_radius_m;
  previous_encoders_ = encoders;

  const double ds = 0.5 * (left_m + right_m);
  const double dtheta_encoders = (right_m - left_m) / geometry_.track_m;
  const double w = gyro_seen_ ? options_.gyro_weight : 0.0;
  const double dtheta = w * gyro_angle_rad_ + (1.0 - w) * dtheta_encoders;
  gyro_angle_rad_ = 0.0;

  const double heading = X_WR_.theta_rad + 0.5 * dtheta;  // midpoint rule
  X_WR_.x_m += ds * std::cos(heading);
  X_WR_.y_m += ds * std::sin(heading);
  X_WR_.theta_rad = plywood::msgs::WrapAngle(X_WR_.theta_rad + dtheta);
}

}  // namespace lab
