#pragma once

#include "msgs/pose2d.h"
#include "robot/odometry/dead_reckoning.h"
#include "robot/odometry/odometry_increments.h"

namespace plywood::robot {

struct WeightedFusedOdometryOptions {
  IncrementOptions increments;
  double encoder_gain = 1.0;  // c_enco
  double gyro_gain = 1.0;     // c_gyro

  // @throws std::invalid_argument naming the offending field.
  void Validate() const;
};

// Seed 004 eq. 5: each sensor's heading change is scaled by its own factor before the mean,
//   dtheta = (c_enco dtheta_enc + c_gyro dtheta_gyro) / 2;
// the seed chose the factors by grid search against ground truth. With both at 1 it is eq. 4.
class WeightedFusedOdometry final : public DeadReckoning {
 public:
  WeightedFusedOdometry(const OdometryGeometry& geometry,
                        const WeightedFusedOdometryOptions& options,
                        const msgs::Pose2D& X_WR_initial);

 private:
  double HeadingChange(const OdometryIncrement& increment) const override {
    return (encoder_gain_ * increment.dtheta_encoder_rad + gyro_gain_ * increment.dtheta_gyro_rad) /
           2.0;
  }

  double encoder_gain_;
  double gyro_gain_;
};

}  // namespace plywood::robot
