#pragma once

namespace plywood::msgs {

// Commanded angular speed of each drive wheel; positive drives the robot forward.
struct WheelSpeedCommand {
  double left_rad_s = 0.0;
  double right_rad_s = 0.0;
};

}  // namespace plywood::msgs
