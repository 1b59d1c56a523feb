#pragma once

#include <charconv>
#include <string>

namespace plywood::msgs {

// `value` in the shortest text that reads back to the same double ("1e-09", "0.25", "inf"), for
// error messages: std::to_string prints 1e-9 as "0.000000" and 1e300 as 301 digits.
inline std::string ShortestNumber(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

}  // namespace plywood::msgs
