#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"

namespace plywood::robot::internal {

// A heading gain (seed 004's factor c): finite and within a factor of two of 1, since anything
// further is no longer a correction of a sensor but a different sensor.
inline void RequireGain(const std::string& field, double value) {
  if (!std::isfinite(value) || value < 0.5 || value > 2.0) {
    throw std::invalid_argument(field + ": must be a finite number in [0.5, 2], got " +
                                msgs::ShortestNumber(value));
  }
}

}  // namespace plywood::robot::internal
