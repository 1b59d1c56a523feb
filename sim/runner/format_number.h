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

// `time_s` on a simulation clock that advances by `timestep_s`, at the precision of the timestep:
// rounded to as many decimals as the timestep's shortest decimal form has (at most 9), as the
// double nearest that decimal, so FormatNumber writes "0.1" where the clock's running sum of
// fifty 0.002 s steps holds 0.10000000000000007. The same inputs give the same bytes.
double TimeAtStepPrecision(double time_s, double timestep_s);

}  // namespace plywood::sim
