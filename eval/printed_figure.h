#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace plywood::eval {

// A figure of a printed summary or table in `format` (one printf conversion of a double, e.g.
// "%9.4f"), or "null" where it is undefined (NaN or infinite: metrics.json's null), right-aligned
// in the width the number would take: a table never shows "nan" (s63).
inline std::string PrintedFigure(double value, const char* format) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  if (std::isfinite(value)) return text;
  const std::string word = "null";
  const std::size_t width = std::max(std::string(text).size(), word.size());
  return std::string(width - word.size(), ' ') + word;
}

// The same with its unit after a finite figure ("0.0123 m"); "null" alone without one.
inline std::string PrintedFigure(double value, const char* format, const std::string& unit) {
  return std::isfinite(value) ? PrintedFigure(value, format) + " " + unit : "null";
}

}  // namespace plywood::eval
