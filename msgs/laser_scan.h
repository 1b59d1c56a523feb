#pragma once

#include <cstddef>
#include <vector>

#include "msgs/pose2d.h"

namespace plywood::msgs {

// One planar sweep of a scanning range finder (SICK LMS 200, a rotating IR head, a CARMEN FLASER
// line). Beam i points at angle_min_rad + i * angle_increment_rad in the sensor frame, counter-
// clockwise from the sensor's x axis. A range >= range_max_m means "no return", as the real
// sensors report it; there is no separate validity flag to keep logs and live data identical.
struct LaserScan {
  double time_s = 0.0;
  double angle_min_rad = 0.0;
  double angle_increment_rad = 0.0;
  double range_min_m = 0.0;
  double range_max_m = 0.0;
  Pose2D X_RS;  // sensor pose in the robot frame
  std::vector<double> ranges_m;

  double BeamAngleRad(std::size_t i) const {
    return angle_min_rad + static_cast<double>(i) * angle_increment_rad;
  }
  bool IsReturn(std::size_t i) const {
    return ranges_m[i] >= range_min_m && ranges_m[i] < range_max_m;
  }
};

}  // namespace plywood::msgs
