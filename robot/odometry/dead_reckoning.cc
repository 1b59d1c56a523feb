#include "robot/odometry/dead_reckoning.h"

namespace plywood::robot {

DeadReckoning::DeadReckoning(const OdometryGeometry& geometry, const IncrementOptions& options,
                             bool uses_gyro, const msgs::Pose2D& X_WR_initial)
    : source_(geometry, options, uses_gyro), X_WR_(X_WR_initial) {}

void DeadReckoning::AddEncoders(const msgs::WheelEncoders& encoders) {
  source_.AddEncoders(encoders);
  Drain();
}

void DeadReckoning::AddGyro(const msgs::GyroRate& gyro) {
  source_.AddGyro(gyro);
  Drain();
}

void DeadReckoning::Drain() {
  while (const auto increment = source_.Next()) {
    X_WR_ =
        Integrate(source_.options().integration, X_WR_, increment->ds_m, HeadingChange(*increment));
  }
}

}  // namespace plywood::robot
