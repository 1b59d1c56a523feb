#include "robot/odometry/encoder_odometry.h"

#include "robot/odometry/odometry_gain.h"

namespace plywood::robot {

void EncoderOdometryOptions::Validate() const {
  increments.Validate();
  internal::RequireGain("gain", gain);
}

EncoderOdometry::EncoderOdometry(const DiffDriveSpec& nominal, const msgs::Pose2D& X_WR_initial)
    : EncoderOdometry(CalibratedGeometry(nominal, {}), {}, X_WR_initial) {}

EncoderOdometry::EncoderOdometry(const OdometryGeometry& geometry,
                                 const EncoderOdometryOptions& options,
                                 const msgs::Pose2D& X_WR_initial)
    : DeadReckoning(geometry, (options.Validate(), options.increments), /*uses_gyro=*/false,
                    X_WR_initial),
      gain_(options.gain) {}

}  // namespace plywood::robot
