#include "robot/odometry/fused_odometry.h"

namespace plywood::robot {

FusedOdometry::FusedOdometry(const OdometryGeometry& geometry, const FusedOdometryOptions& options,
                             const msgs::Pose2D& X_WR_initial)
    : DeadReckoning(geometry, (options.Validate(), options.increments), /*uses_gyro=*/true,
                    X_WR_initial) {}

}  // namespace plywood::robot
