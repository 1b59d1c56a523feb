#pragma once

#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"

namespace plywood::perception {

// The check behind the geometric map's Validate()s: throws std::invalid_argument "<field>: <what>,
// got <value>", so the message starts with the field's name as the YAML layer spells it. NaN fails
// every range written as `ok` = (lo <= v && v <= hi).
inline void RequireOption(bool ok, const char* field, const char* what, double value) {
  if (!ok) {
    throw std::invalid_argument(std::string(field) + ": " + what + ", got " +
                                msgs::ShortestNumber(value));
  }
}

}  // namespace plywood::perception
