// The number parser every reader shares (perception/logs/parse_number.h): what it accepts is
// finite, is what strtod reads from the same whole text, and survives the shortest round trip.
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "fuzz/fuzz_support.h"
#include "fuzz/fuzz_target.h"
#include "perception/logs/parse_number.h"

namespace plywood::fuzz {
namespace {

void FuzzParseNumber(std::span<const std::uint8_t> data) {
  const std::string text = AsText(data);
  const std::optional<double> value = perception::ParseFiniteNumber(text);
  if (!value) return;
  Require(std::isfinite(*value), "a non-finite number accepted: " + text);
  Require(text.find('\0') == std::string::npos, "text with a NUL byte accepted");
  // strtod (the C locale is in force in a fresh process) reads the same decimal to the same double.
  char* end = nullptr;
  const double reference = std::strtod(text.c_str(), &end);
  Require(end == text.c_str() + text.size() && reference == *value,
          "disagrees with strtod on: " + text);
  char shortest[64];
  const auto written = std::to_chars(shortest, shortest + sizeof(shortest), *value);
  const std::optional<double> again =
      perception::ParseFiniteNumber(std::string_view(shortest, written.ptr));
  Require(again && *again == *value, "the shortest form does not read back: " + text);
}

}  // namespace
}  // namespace plywood::fuzz

PLYWOOD_FUZZ_TARGET("parse_number", plywood::fuzz::FuzzParseNumber)
