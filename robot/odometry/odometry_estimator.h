#pragma once

#include "msgs/gyro_rate.h"
#include "msgs/pose2d.h"
#include "msgs/wheel_encoders.h"

namespace plywood::robot {

// A dead-reckoning pose estimator fed plain sensor messages in time order, exactly as on the
// robot. Implementations use the robot's nominal geometry, never the simulator's.
class OdometryEstimator {
 public:
  OdometryEstimator() = default;
  OdometryEstimator(const OdometryEstimator&) = delete;
  OdometryEstimator& operator=(const OdometryEstimator&) = delete;
  virtual ~OdometryEstimator() = default;

  // Readings out of time order or without a finite time are dropped, and a tick jump only a
  // counter wrap explains throws std::invalid_argument naming the wheel (IncrementSource).
  virtual void AddEncoders(const msgs::WheelEncoders& encoders) = 0;
  // Estimators that do not use a gyro ignore it; those that do drop a sample whose rate or time is
  // not finite.
  virtual void AddGyro(const msgs::GyroRate& /*gyro*/) {}

  // X_WR: the estimated pose of the robot in the frame of its initial pose estimate.
  virtual msgs::Pose2D pose() const = 0;
};

}  // namespace plywood::robot
