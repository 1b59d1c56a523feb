#pragma once

#include <optional>

#include "msgs/pose2d.h"
#include "msgs/wheel_encoders.h"
#include "robot/diff_drive_spec.h"
#include "robot/odometry_estimator.h"

namespace plywood::robot {

// Dead reckoning from wheel encoders alone with midpoint integration (seed 004 eq. 3), using the
// robot's nominal geometry: whatever the real wheels are, this is what the robot believes.
class EncoderOdometry final : public OdometryEstimator {
 public:
  EncoderOdometry(const DiffDriveSpec& nominal, const msgs::Pose2D& X_WR_initial);

  // Integrates the motion since the previous reading; the first reading only sets the reference.
  void Update(const msgs::WheelEncoders& encoders);
  void AddEncoders(const msgs::WheelEncoders& encoders) override { Update(encoders); }

  msgs::Pose2D pose() const override { return X_WR_; }

 private:
  DiffDriveSpec nominal_;
  msgs::Pose2D X_WR_;
  std::optional<msgs::WheelEncoders> previous_;
};

}  // namespace plywood::robot
