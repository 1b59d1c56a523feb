#pragma once

#include <cstdint>
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
  using Value = std::variant<double, std::string, std::uint64_t>;

  void Set(const std::string& key, double value) { values_[key] = value; }
  void Set(const std::string& key, const std::string& value) { values_[key] = value; }
  // A whole number written exactly (the run's seed): a double holds whole numbers only up to 2^53,
  // and seed 2^53 + 1 read back as 2^53 in metrics.json.
  void SetWholeNumber(const std::string& key, std::uint64_t value) { values_[key] = value; }
  const std::map<std::string, Value>& values() const { return values_; }
  // @throws std::out_of_range when absent, std::bad_variant_access when not a number.
  double Number(const std::string& key) const {
    const Value& value = values_.at(key);
    if (const auto* whole = std::get_if<std::uint64_t>(&value)) return static_cast<double>(*whole);
    return std::get<double>(value);
  }

  // @throws std::invalid_argument when a key is both a value and a prefix of another key.
  std::string ToJson() const;

 private:
  std::map<std::string, Value> values_;
};

}  // namespace plywood::sim
