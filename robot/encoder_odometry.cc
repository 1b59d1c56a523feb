#include "robot/encoder_odometry.h"

#include <numbers>

#include "robot/diff_drive_kinematics.h"

namespace plywood::robot {

EncoderOdometry::EncoderOdometry(const DiffDriveSpec& nominal, const msgs::Pose2D& X_WR_initial)
    : nominal_(nominal), X_WR_(X_WR_initial) {
  nominal_.Validate();
}

void EncoderOdometry::Update(const msgs::WheelEncoders& encoders) {
  if (previous_) {
    const double radians_per_tick = 2.0 * std::numbers::pi / nominal_.encoder_ticks_per_rev;
    const double left_m =
        nominal_.wheel_radius_m * radians_per_tick * (encoders.left_ticks - previous_->left_ticks);
    const double right_m = nominal_.wheel_radius_m * radians_per_tick *
                           (encoders.right_ticks - previous_->right_ticks);
    X_WR_ =
        IntegrateMidpoint(X_WR_, (left_m + right_m) / 2.0, (right_m - left_m) / nominal_.track_m);
  }
  previous_ = encoders;
}

}  // namespace plywood::robot
