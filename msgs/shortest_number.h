#pragma once

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace plywood::msgs {

// `value` in the shortest text that reads back to the same double ("1e-09", "0.25", "inf"), for
// error messages: std::to_string prints 1e-9 as "0.000000" and 1e300 as 301 digits.
inline std::string ShortestNumber(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

// `value` rounded to six significant digits, then as ShortestNumber: for limits derived by
// arithmetic, so 1.2 - 0.8 (0.3999999999999999) reads 0.4 and 9.75e-11 is not printed as 0.
inline std::string SixDigitNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.6g", value);
  return ShortestNumber(std::strtod(buffer, nullptr));
}

}  // namespace plywood::msgs
