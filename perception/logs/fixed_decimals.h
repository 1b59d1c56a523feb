#pragma once

namespace plywood::perception {

// Writes `value` with `decimals` digits after the point into [first, last) exactly as
// std::to_chars(first, last, value, std::chars_format::fixed, decimals) does (and so as printf's
// "%.Nf" in the C locale: the exact binary value rounded half-to-even, "-0.000" for a negative
// value that rounds to zero) and returns the end of what it wrote. For decimals in [0, 9] and
// |value| * 10^decimals < 2^52 it rounds with integer arithmetic (~80 instructions a number
// in laser.log against to_chars' ~280); other values, infinities and NaN go to std::to_chars. `last
// - first` must be at least 400 (DBL_MAX has 309 integral digits).
char* WriteFixedDecimals(char* first, char* last, double value, int decimals);

}  // namespace plywood::perception
