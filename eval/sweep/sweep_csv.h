#pragma once

#include <string>
#include <vector>

namespace plywood::eval {

// One RFC 4180 row ending in "\n": fields with a comma, quote or line break are quoted.
std::string CsvRow(const std::vector<std::string>& fields);

// Splits RFC 4180 text into rows of fields (quoted fields may hold commas, quotes and newlines).
std::vector<std::vector<std::string>> ParseCsv(const std::string& text);

}  // namespace plywood::eval
