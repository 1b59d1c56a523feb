#pragma once

#include <filesystem>
#include <string>

#include "sim/config/utf8_text.h"
#include "sim/runner/metrics.h"

namespace plywood::eval {

// What `plywood score` found: the metrics under the same keys as a run's metrics.json, and a
// table for people.
struct ScoreReport {
  sim::Metrics metrics;
  std::string table;
};

// Refuses (sim::ConfigError, one line naming --out) a scores file that could not be written: a
// name that ends in a folder ('/', '.', '..'), a folder, a target inside the scored run's folder or
// equal to the scored file. Called before scoring, so no table is printed for a refused --out.
void CheckScoreOut(const std::filesystem::path& out, const std::filesystem::path& run_dir,
                   const std::filesystem::path& scored);

// Writes report.metrics as JSON to `out` (`plywood score --out`). Refuses (sim::ConfigError, one
// line) what CheckScoreOut refuses, so a score never overwrites what it scored, and reports a
// target it cannot write the same way.
void WriteScoreJson(const ScoreReport& report, const std::filesystem::path& out,
                    const std::filesystem::path& run_dir, const std::filesystem::path& scored);

// Whether `name` can be one part of a dotted metrics key: not empty, no dot, no white space, no
// comma or quote (it also goes into CSV and JSON), and UTF-8 text (JSON's: other bytes would be
// written as U+FFFD, a key other than the name given).
inline bool IsMetricName(const std::string& name) {
  return !name.empty() && name.find_first_of(". \t\r\n,\"") == std::string::npos &&
         sim::IsUtf8(name);
}

// What an error says of a `name` IsMetricName refuses: the rule, once for every reader.
inline std::string NotAMetricName(const std::string& name) {
  return "'" + name + "' cannot name a metric (no dots, commas or spaces; UTF-8 text)";
}

}  // namespace plywood::eval
