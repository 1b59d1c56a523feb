#include "sim/runner/format_number.h"

#include <charconv>
#include <cmath>

namespace plywood::sim {

std::string FormatNumber(double value) {
  if (!std::isfinite(value)) return "null";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

std::string FormatFixed(double value, int decimals) {
  if (!std::isfinite(value)) return "null";
  char buffer[400];  // DBL_MAX has 309 integral digits
  const auto result =
      std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::fixed, decimals);
  std::string text(buffer, result.ptr);
  if (text.starts_with('-') && text.find_first_not_of("0.", 1) == std::string::npos) {
    text.erase(0, 1);
  }
  return text;
}

double TimeAtStepPrecision(double time_s, double timestep_s) {
  const auto read_back = [](const std::string& text) {
    double value = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), value);
    return value;
  };
  int decimals = 0;
  while (decimals < 9 && read_back(FormatFixed(timestep_s, decimals)) != timestep_s) ++decimals;
  return std::isfinite(time_s) ? read_back(FormatFixed(time_s, decimals)) : time_s;
}

}  // namespace plywood::sim
