#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace plywood::apps {

// A transform for every whole-number flag: decimal digits (one leading sign allowed), leading
// zeros dropped. CLI11 converts integers with C's base detection (strtoll base 0), so `--count
// 010` made 8 worlds and `train --seed 0x10` trained with seed 16, where `run --seed 010` runs
// seed 10 and refuses 0x10 (docs/errors.md, seventh pass).
inline CLI::Validator DecimalWholeNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::size_t digits = !text.empty() && (text[0] == '-' || text[0] == '+') ? 1 : 0;
        if (text.size() == digits ||
            text.find_first_not_of("0123456789", digits) != std::string::npos) {
          return "expected a whole number in decimal digits, got '" + text + "'";
        }
        const std::size_t first = text.find_first_not_of('0', digits);
        text.erase(digits, (first == std::string::npos ? text.size() - 1 : first) - digits);
        return std::string();
      },
      "", "decimal");
}

}  // namespace plywood::apps
