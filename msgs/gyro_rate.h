#pragma once

namespace plywood::msgs {

// Yaw rate from a single-axis rate gyro about the robot's vertical axis, counter-clockwise
// positive.
struct GyroRate {
  double time_s = 0.0;
  double yaw_rate_rad_s = 0.0;
};

}  // namespace plywood::msgs
