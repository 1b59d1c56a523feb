#pragma once

#include <charconv>
#include <cmath>
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

// Metres to the millimetre, for messages ("0.255", not "0.25500000000000006").
inline std::string MillimetreNumber(double metres) {
  return ShortestNumber(std::round(metres * 1000.0) / 1000.0);
}

// `value` to six significant digits rounded down (AtMost) or up (AtLeast), then as ShortestNumber:
// for a limit printed as "at most X" or "at least X", which X itself must meet. Rounding to the
// nearest printed 1 / 0.0301 s as 33.2226 Hz, above the 33.22259... Hz limit, so the number the
// message gave was refused in turn.
inline std::string SixDigitNumberToward(double value, double direction) {
  if (!std::isfinite(value) || value == 0.0) return ShortestNumber(value);
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.5e", value);
  double rounded = std::strtod(buffer, nullptr);
  if ((rounded - value) * direction < 0.0) {
    // One unit in the sixth digit of `value` (999999.7 prints as 1.00000e+06: not its exponent).
    rounded += direction * std::pow(10.0, std::floor(std::log10(std::fabs(value))) - 5.0);
    std::snprintf(buffer, sizeof(buffer), "%.5e", rounded);
    rounded = std::strtod(buffer, nullptr);
  }
  return ShortestNumber(rounded);
}
inline std::string SixDigitNumberAtMost(double value) { return SixDigitNumberToward(value, -1.0); }
inline std::string SixDigitNumberAtLeast(double value) { return SixDigitNumberToward(value, 1.0); }

}  // namespace plywood::msgs
