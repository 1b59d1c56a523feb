#pragma once

#include "msgs/pose2d.h"
#include "robot/odometry/dead_reckoning.h"
#include "robot/odometry/odometry_increments.h"

namespace plywood::robot {

struct FusedOdometryOptions {
  IncrementOptions increments;

  // @throws std::invalid_argument naming the offending field.
  void Validate() const { increments.Validate(); }
};

// Seed 004 eq. 4: the heading change is the plain mean of the encoders' and the gyro's,
//   dtheta = (dtheta_enc + dtheta_gyro) / 2,
// which helps exactly when the two err in opposite directions (encoders under-turning, the gyro
// over-turning, as in the seed).
class FusedOdometry final : public DeadReckoning {
 public:
  FusedOdometry(const OdometryGeometry& geometry, const FusedOdometryOptions& options,
                const msgs::Pose2D& X_WR_initial);

 private:
  double HeadingChange(const OdometryIncrement& increment) const override {
    return (increment.dtheta_encoder_rad + increment.dtheta_gyro_rad) / 2.0;
  }
};

}  // namespace plywood::robot
