#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"

// Option checks shared by the robot layer's Validate() functions; messages start with the field
// name, so the caller's error names the file and field.
namespace plywood::robot::internal {

inline void RequirePositive(const std::string& field, double value) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument(field + ": must be a finite number > 0, got " +
                                msgs::ShortestNumber(value));
  }
}

inline void RequireNonNegative(const std::string& field, double value) {
  if (!std::isfinite(value) || value < 0.0) {
    throw std::invalid_argument(field + ": must be a finite number >= 0, got " +
                                msgs::ShortestNumber(value));
  }
}

}  // namespace plywood::robot::internal
