#pragma once

#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"

namespace plywood::sim {

// The check behind the sensors' Validate(): throws std::invalid_argument "<field>: <what>, got
// <value>", so the message starts with the field's name as the YAML layer spells it.
inline void RequireField(bool ok, const std::string& field, const std::string& what, double value) {
  if (!ok) {
    throw std::invalid_argument(field + ": " + what + ", got " + msgs::ShortestNumber(value));
  }
}

}  // namespace plywood::sim
