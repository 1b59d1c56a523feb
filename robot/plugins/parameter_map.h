#pragma once

// Header-only on purpose: a plug-in (docs/plugins.md) calls these functions on objects the host
// made, so they must not depend on globals of either side's copy of the static libraries.

#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace plywood::robot {

// The options of a registered algorithm (a line extractor, odometry estimator or controller added
// through a registry): text by key, exactly as written in the experiment YAML
// (`my_filter: {gain: 0.5}` gives {"gain": "0.5"}). The factory reads each option with a typed
// getter, which checks the type and the range and throws std::invalid_argument "<key>: <what is
// wrong>"; afterwards the host calls CheckAllRead(), so a misspelt key is an error instead of an
// option silently left at its default.
class ParameterMap {
 public:
  ParameterMap() = default;
  explicit ParameterMap(std::map<std::string, std::string> values) : values_(std::move(values)) {}

  void Set(const std::string& key, std::string value) { values_[key] = std::move(value); }
  bool Has(const std::string& key) const { return values_.count(key) > 0; }
  const std::map<std::string, std::string>& values() const { return values_; }
  bool empty() const { return values_.empty(); }

  // A finite number in [min, max]; `fallback` when the key is absent.
  double GetDouble(const std::string& key, double fallback,
                   double min = -std::numeric_limits<double>::infinity(),
                   double max = std::numeric_limits<double>::infinity()) const {
    const std::string* text = Find(key);
    if (!text) return fallback;
    double value = 0.0;
    const char* end = text->data() + text->size();
    const auto [ptr, error] = std::from_chars(text->data(), end, value);
    if (error != std::errc() || ptr != end || !std::isfinite(value)) {
      Fail(key, "expected a finite number", *text);
    }
    if (value < min || value > max) Fail(key, "expected a number " + Range(min, max), *text);
    return value;
  }

  // A whole number in [min, max]; `fallback` when the key is absent.
  int GetInt(const std::string& key, int fallback, int min = INT_MIN, int max = INT_MAX) const {
    const std::string* text = Find(key);
    if (!text) return fallback;
    long long value = 0;
    const char* end = text->data() + text->size();
    const auto [ptr, error] = std::from_chars(text->data(), end, value);
    if (error != std::errc() || ptr != end) Fail(key, "expected a whole number", *text);
    if (value < min || value > max) {
      Fail(key, "expected a whole number " + Range(min, max), *text);
    }
    return static_cast<int>(value);
  }

  // true or false; `fallback` when the key is absent.
  bool GetBool(const std::string& key, bool fallback) const {
    const std::string* text = Find(key);
    if (!text) return fallback;
    if (*text == "true") return true;
    if (*text == "false") return false;
    Fail(key, "expected true or false", *text);
  }

  // Any text; `fallback` when the key is absent.
  std::string GetString(const std::string& key, const std::string& fallback) const {
    const std::string* text = Find(key);
    return text ? *text : fallback;
  }

  // @throws std::invalid_argument "<key>: unknown key (known here: ...)" for the first key that no
  // getter asked for (the known keys are those the getters asked for).
  void CheckAllRead() const {
    for (const auto& entry : values_) {
      if (asked_.count(entry.first)) continue;
      std::string known;
      for (const std::string& k : asked_) known += (known.empty() ? "" : ", ") + k;
      throw std::invalid_argument(entry.first + ": unknown key" +
                                  (known.empty() ? std::string(" (this algorithm takes no options)")
                                                 : " (known here: " + known + ")"));
    }
  }

 private:
  const std::string* Find(const std::string& key) const {
    asked_.insert(key);
    const auto it = values_.find(key);
    return it == values_.end() ? nullptr : &it->second;
  }

  [[noreturn]] static void Fail(const std::string& key, const std::string& what,
                                const std::string& text) {
    throw std::invalid_argument(key + ": " + what + ", got '" + text + "'");
  }

  static std::string Number(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.10g", value);
    return buffer;
  }

  static std::string Range(double min, double max) {
    const bool has_min = min > -std::numeric_limits<double>::max();
    const bool has_max = max < std::numeric_limits<double>::max();
    if (has_min && has_max) return "in [" + Number(min) + ", " + Number(max) + "]";
    if (has_min) return ">= " + Number(min);
    return "<= " + Number(max);
  }

  static std::string Range(int min, int max) {
    if (min > INT_MIN && max < INT_MAX) {
      return "in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
    }
    if (min > INT_MIN) return ">= " + std::to_string(min);
    return "<= " + std::to_string(max);
  }

  std::map<std::string, std::string> values_;
  mutable std::set<std::string> asked_;  // every key a getter asked for, present or not
};

}  // namespace plywood::robot
