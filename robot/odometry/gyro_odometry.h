#pragma once

#include "msgs/pose2d.h"
#include "robot/odometry/dead_reckoning.h"
#include "robot/odometry/odometry_increments.h"

namespace plywood::robot {

struct GyroOdometryOptions {
  IncrementOptions increments;
  // Seed 004's "filtering" factor on the gyro heading change (the seed lowered it below 1 because
  // its gyro over-turned).
  double gain = 1.0;

  // @throws std::invalid_argument naming the offending field.
  void Validate() const;
};

// Seed 004's second variant: distance from the encoders, heading change from the rate gyro
// integrated over the same interval (the gyro's bias and scale error go straight into the heading).
class GyroOdometry final : public DeadReckoning {
 public:
  GyroOdometry(const OdometryGeometry& geometry, const GyroOdometryOptions& options,
               const msgs::Pose2D& X_WR_initial);

 private:
  double HeadingChange(const OdometryIncrement& increment) const override {
    return gain_ * increment.dtheta_gyro_rad;
  }

  double gain_;
};

}  // namespace plywood::robot
