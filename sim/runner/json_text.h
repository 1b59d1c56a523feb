#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace plywood::sim {

// How WriteJson lays a document out.
struct JsonStyle {
  // kOneItemPerLine: an object is written one member per line (indented two spaces a level), an
  // array of containers one element per line; an array of scalars, and anything inside an array,
  // stays on one line: {"room": [0, 0, 3, 2], "partitions": [\n    {"rect": [...], ...},\n ...]}.
  // kOneLine: the whole document on one line.
  enum class Layout { kOneItemPerLine, kOneLine };
  Layout layout = Layout::kOneItemPerLine;
  // Floating-point numbers in shortest round-trip form (FormatNumber) when negative, else fixed
  // with this many decimals (FormatFixed). Integers are always written as integers.
  int fixed_decimals = -1;
};

// `json` as text ending in a newline, with ", " and ": " between items. nlohmann's own dump is
// not used for numbers: it writes 12.0 for 12, 0.0001 where std::to_chars writes 1e-04 and its
// Grisu2 is not always the shortest, so the bytes would depend on the library, not the value.
// Strings are escaped by nlohmann (invalid UTF-8 replaced). Key order is the object's own: sorted
// for nlohmann::json, insertion order for nlohmann::ordered_json.
std::string WriteJson(const nlohmann::json& json, const JsonStyle& style = {});
std::string WriteJson(const nlohmann::ordered_json& json, const JsonStyle& style = {});

}  // namespace plywood::sim
