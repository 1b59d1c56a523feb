#pragma once

#include <optional>

#include "msgs/gyro_rate.h"
#include "msgs/pose2d.h"
#include "msgs/wheel_encoders.h"
#include "robot/odometry/odometry_estimator.h"
#include "robot/odometry/odometry_increments.h"

namespace lab {

struct ComplementaryOptions {
  // Share of each heading change taken from the gyro; the rest comes from the encoders.
  double gyro_weight = 0.9;
};

// Encoder odometry whose heading change is a complementary blend of the gyro's and the encoders',
// written from scratch for this example: distance from the wheels, heading mostly from the gyro
// (which does not see wheel slip or a wrong track width). The gyro angle used for an encoder
// interval is what the gyro reported since the previous encoder reading.
class ComplementaryOdometry final : public plywood::robot::OdometryEstimator {
 public:
  ComplementaryOdometry(const plywood::robot::OdometryGeometry& geometry,
                        const ComplementaryOptions& options,
                        const plywood::msgs::Pose2D& X_WR_initial)
      : geometry_(geometry), options_(options), X_WR_(X_WR_initial) {}

  void AddEncoders(const plywood::msgs::WheelEncoders& encoders) override;
  void AddGyro(const plywood::msgs::GyroRate& gyro) override;
  plywood::msgs::Pose2D pose() const override { return X_WR_; }

 private:
  plywood::robot::OdometryGeometry geometry_;
  ComplementaryOptions options_;
  plywood::msgs::Pose2D X_WR_;
  std::optional<plywood::msgs::WheelEncoders> previous_encoders_;
  std::optional<double> previous_gyro_s_;
  double gyro_angle_rad_ = 0.0;  // integrated since the previous encoder reading
  bool gyro_seen_ = false;
};

}  // namespace lab
