#pragma once

#include "msgs/gyro_rate.h"
#include "msgs/pose2d.h"
#include "msgs/wheel_encoders.h"
#include "robot/odometry/odometry_estimator.h"
#include "robot/odometry/odometry_increments.h"

namespace plywood::robot {

// The common body of seed 004's estimators: distance from the encoders, a heading change chosen by
// the subclass from the encoder and gyro increments, integrated step by step (eq. 3).
class DeadReckoning : public OdometryEstimator {
 public:
  void AddEncoders(const msgs::WheelEncoders& encoders) final;
  void AddGyro(const msgs::GyroRate& gyro) final;
  msgs::Pose2D pose() const final { return X_WR_; }

 protected:
  DeadReckoning(const OdometryGeometry& geometry, const IncrementOptions& options, bool uses_gyro,
                const msgs::Pose2D& X_WR_initial);

  // The heading change (rad) to integrate for `increment`.
  virtual double HeadingChange(const OdometryIncrement& increment) const = 0;

 private:
  void Drain();

  IncrementSource source_;
  msgs::Pose2D X_WR_;
};

}  // namespace plywood::robot
