#include "sim/runner/metrics.h"

#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "sim/runner/json_text.h"

namespace plywood::sim {
namespace {

std::vector<std::string> SplitKey(const std::string& key) {
  std::vector<std::string> parts;
  std::stringstream stream(key);
  for (std::string part; std::getline(stream, part, '.');) parts.push_back(part);
  return parts;
}

}  // namespace

std::string Metrics::ToJson() const {
  nlohmann::json root = nlohmann::json::object();
  for (const auto& [key, value] : values_) {
    const auto next = values_.lower_bound(key + ".");
    if (next != values_.end() && next->first.starts_with(key + ".")) {
      throw std::invalid_argument("metrics key '" + key + "' is also an object");
    }
    const std::vector<std::string> parts = SplitKey(key);
    if (parts.empty()) throw std::invalid_argument("metrics key '" + key + "' names nothing");
    nlohmann::json* object = &root;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) object = &(*object)[parts[i]];
    nlohmann::json& leaf = (*object)[parts.back()];
    if (const double* number = std::get_if<double>(&value)) {
      leaf = *number;
    } else if (const auto* whole = std::get_if<std::uint64_t>(&value)) {
      leaf = *whole;
    } else {
      leaf = std::get<std::string>(value);
    }
  }
  return WriteJson(root);
}

}  // namespace plywood::sim
