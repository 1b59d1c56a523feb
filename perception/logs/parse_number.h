#pragma once

#include <optional>
#include <string_view>

namespace plywood::perception {

// The whole of `text` as a finite decimal number ("3", "-0.25", "1e-3"), independent of the C
// locale; nullopt for anything else (empty, trailing text, NaN, infinities, out of range). Every
// text reader (logs, weight files, YAML, the command line) parses numbers through this one rule.
std::optional<double> ParseFiniteNumber(std::string_view text);

}  // namespace plywood::perception
