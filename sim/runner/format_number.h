#pragma once

#include <string>

namespace plywood::sim {

// Shortest decimal text that reads back to exactly `value` ("0.1", "1e-07", "12"); "null" for
// NaN and infinities, which JSON cannot hold. std::to_chars ignores the locale, so every machine
// writes the same bytes.
std::string FormatNumber(double value);

// `value` with exactly `decimals` digits after the point ("1.5000"); "-0.0000" is written as
// "0.0000" (the same place); "null" for NaN and infinities.
std::string FormatFixed(double value, int decimals);

}  // namespace plywood::sim
