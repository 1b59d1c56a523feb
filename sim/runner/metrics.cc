#include "sim/runner/metrics.h"

#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace plywood::sim {
namespace {

std::vector<std::string> SplitKey(const std::string& key) {
  std::vector<std::string> parts;
  std::stringstream stream(key);
  for (std::string part; std::getline(stream, part, '.');) parts.push_back(part);
  return parts;
}

std::string Quote(const std::string& text) {
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    if (c == '\n') {
      quoted += "\\n";
      continue;
    }
    quoted += c;
  }
  return quoted + "\"";
}

}  // namespace

std::string FormatNumber(double value) {
  if (!std::isfinite(value)) return "null";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

namespace {

// Appends only: GCC 12 at -O3 reports a false -Werror=restrict on "\n" + std::string(...)
// (operator+ inserting at the front of a temporary).
void StartMember(std::string& json, bool first_in_object, std::size_t depth,
                 const std::string& name) {
  if (!first_in_object) json += ',';
  json += '\n';
  json.append(2 * depth, ' ');
  json += Quote(name);
  json += ": ";
}

void CloseObject(std::string& json, std::size_t depth) {
  json += '\n';
  json.append(2 * depth, ' ');
  json += '}';
}

}  // namespace

std::string Metrics::ToJson() const {
  // Keys are sorted, so a depth-first walk opens and closes objects by comparing each key's path
  // with the previous one.
  for (const auto& [key, value] : values_) {
    const auto next = values_.lower_bound(key + ".");
    if (next != values_.end() && next->first.starts_with(key + ".")) {
      throw std::invalid_argument("metrics key '" + key + "' is also an object");
    }
  }
  std::string json = "{";
  std::vector<std::string> open;  // currently open object path
  bool first_in_object = true;
  for (const auto& [key, value] : values_) {
    const std::vector<std::string> parts = SplitKey(key);
    std::size_t common = 0;
    while (common < open.size() && common + 1 < parts.size() && open[common] == parts[common]) {
      ++common;
    }
    while (open.size() > common) {
      CloseObject(json, open.size());
      open.pop_back();
      first_in_object = false;
    }
    for (std::size_t i = common; i + 1 < parts.size(); ++i) {
      StartMember(json, first_in_object, open.size() + 1, parts[i]);
      json += '{';
      open.push_back(parts[i]);
      first_in_object = true;
    }
    StartMember(json, first_in_object, open.size() + 1, parts.back());
    json += std::holds_alternative<double>(value) ? FormatNumber(std::get<double>(value))
                                                  : Quote(std::get<std::string>(value));
    first_in_object = false;
  }
  while (!open.empty()) {
    CloseObject(json, open.size());
    open.pop_back();
  }
  return json + "\n}\n";
}

}  // namespace plywood::sim
