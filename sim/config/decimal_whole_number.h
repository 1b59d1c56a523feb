#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace plywood::sim {

// `text` as a whole number >= 0 read in decimal: digits only, at most 19 of them (so it fits in 64
// bits); nullopt otherwise. Seeds are read through this one rule wherever they are given (an
// experiment's `seed:`, `--seed`, a sweep's `seeds:`): yaml-cpp's own conversion reads `010` as 8
// and `0x10` as 16, where an experiment reads 10 and refuses 0x10.
inline std::optional<std::uint64_t> ParseDecimalWholeNumber(const std::string& text) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos ||
      text.size() > 19) {
    return std::nullopt;
  }
  return std::stoull(text);
}

}  // namespace plywood::sim
