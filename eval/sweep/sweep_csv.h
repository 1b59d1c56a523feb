#pragma once

#include <string>
#include <vector>

namespace plywood::eval {

// One RFC 4180 line ending in "\n", each field quoted as CsvField (eval/score/csv_table.h) does.
std::string CsvLine(const std::vector<std::string>& fields);

// Splits RFC 4180 text into rows of fields (quoted fields may hold commas, quotes and newlines).
std::vector<std::vector<std::string>> ParseCsv(const std::string& text);

}  // namespace plywood::eval
