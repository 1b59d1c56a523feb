#pragma once

#include <cstdint>

namespace plywood::msgs {

// Cumulative quadrature counts of the two drive wheels, as a motor controller reports them.
// Positive counts drive the robot forward.
struct WheelEncoders {
  double time_s = 0.0;
  std::int64_t left_ticks = 0;
  std::int64_t right_ticks = 0;
};

}  // namespace plywood::msgs
