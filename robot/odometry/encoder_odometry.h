#pragma once

#include "msgs/pose2d.h"
#include "msgs/wheel_encoders.h"
#include "robot/drive/diff_drive_spec.h"
#include "robot/odometry/dead_reckoning.h"
#include "robot/odometry/odometry_increments.h"

namespace plywood::robot {

struct EncoderOdometryOptions {
  IncrementOptions increments;
  // Seed 004's "filtering": the encoder heading change is multiplied by this factor (the seed
  // raised it above 1 because its encoders under-turned).
  double gain = 1.0;

  // @throws std::invalid_argument naming the offending field.
  void Validate() const;
};

// Dead reckoning from wheel encoders alone with midpoint integration (seed 004 eq. 3), using the
// robot's nominal geometry: whatever the real wheels are, this is what the robot believes.
class EncoderOdometry final : public DeadReckoning {
 public:
  EncoderOdometry(const DiffDriveSpec& nominal, const msgs::Pose2D& X_WR_initial);
  EncoderOdometry(const OdometryGeometry& geometry, const EncoderOdometryOptions& options,
                  const msgs::Pose2D& X_WR_initial);

  // Integrates the motion since the previous reading; the first reading only sets the reference.
  void Update(const msgs::WheelEncoders& encoders) { AddEncoders(encoders); }

 private:
  double HeadingChange(const OdometryIncrement& increment) const override {
    return gain_ * increment.dtheta_encoder_rad;
  }

  double gain_;
};

}  // namespace plywood::robot
