#pragma once

#include <limits>
#include <vector>

#include "msgs/pose2d.h"

namespace plywood::msgs {

// One reading of a single-beam range sensor on a ring (a sonar transducer or an IR emitter).
struct RangeReading {
  Pose2D X_RS;           // transducer pose in the robot frame; x axis along the beam
  double range_m = 0.0;  // meaningful only when echo is true
  bool echo = false;     // false: nothing came back (out of range, or a specular miss)

  // An echo at a usable range. An echo flagged with a NaN, infinite, zero or negative range (a
  // driver's "no return" code) is no echo, for every consumer of the ring.
  bool HeardEcho() const {
    return echo && range_m > 0.0 && range_m < std::numeric_limits<double>::infinity();
  }
};

// A ring of single-beam range sensors read at one instant: the Magellan Pro's and P3-DX's sonar
// rings, the Magellan Pro's IR ring.
struct RangeRing {
  double time_s = 0.0;
  double range_min_m = 0.0;
  double range_max_m = 0.0;
  std::vector<RangeReading> readings;
};

using SonarRing = RangeRing;
using IrRing = RangeRing;

}  // namespace plywood::msgs
