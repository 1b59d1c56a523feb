#include "perception/logs/parse_number.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace plywood::perception {

std::optional<double> ParseFiniteNumber(std::string_view text) {
  // from_chars rejects a leading '+', which hand-written files do use; one sign, not "+-5".
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && text.front() == '-') return std::nullopt;
  }
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || ptr != end || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

}  // namespace plywood::perception
