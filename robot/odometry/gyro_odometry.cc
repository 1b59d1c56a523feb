#include "robot/odometry/gyro_odometry.h"

#include "robot/odometry/odometry_gain.h"

namespace plywood::robot {

void GyroOdometryOptions::Validate() const {
  increments.Validate();
  internal::RequireGain("gain", gain);
}

GyroOdometry::GyroOdometry(const OdometryGeometry& geometry, const GyroOdometryOptions& options,
                           const msgs::Pose2D& X_WR_initial)
    : DeadReckoning(geometry, (options.Validate(), options.increments), /*uses_gyro=*/true,
                    X_WR_initial),
      gain_(options.gain) {}

}  // namespace plywood::robot
