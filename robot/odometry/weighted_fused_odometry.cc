#include "robot/odometry/weighted_fused_odometry.h"

#include "robot/odometry/odometry_gain.h"

namespace plywood::robot {

void WeightedFusedOdometryOptions::Validate() const {
  increments.Validate();
  internal::RequireGain("encoder_gain", encoder_gain);
  internal::RequireGain("gyro_gain", gyro_gain);
}

WeightedFusedOdometry::WeightedFusedOdometry(const OdometryGeometry& geometry,
                                             const WeightedFusedOdometryOptions& options,
                                             const msgs::Pose2D& X_WR_initial)
    : DeadReckoning(geometry, (options.Validate(), options.increments), /*uses_gyro=*/true,
                    X_WR_initial),
      encoder_gain_(options.encoder_gain),
      gyro_gain_(options.gyro_gain) {}

}  // namespace plywood::robot
