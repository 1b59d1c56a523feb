#pragma once

#include <map>
#include <string>
#include <variant>

#include "sim/runner/format_number.h"

namespace plywood::sim {

// The numbers a run reports, keyed by dotted paths ("odometry.encoder.drift_percent"). Written as
// nested JSON objects (nlohmann) with the keys of each object sorted and numbers in shortest
// round-trip form (sim/runner/json_text.h), so the same run gives the same bytes. Wall-clock
// figures never go here: they would break byte-identical reruns.
class Metrics {
 public:
  using Value = std::variant<double, std::string>;

  void Set(const std::string& key, double value) { values_[key] = value; }
  void Set(const std::string& key, const std::string& value) { values_[key] = value; }
  const std::map<std::string, Value>& values() const { return values_; }
  // @throws std::out_of_range when absent or not a number.
  double Number(const std::string& key) const { return std::get<double>(values_.at(key)); }

  // @throws std::invalid_argument when a key is both a value and a prefix of another key.
  std::string ToJson() const;

 private:
  std::map<std::string, Value> values_;
};

}  // namespace plywood::sim
