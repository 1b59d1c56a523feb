#include "eval/sweep/sweep_results.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <utility>

#include "eval/sweep/sweep_csv.h"
#include "eval/sweep/sweep_meta.h"
#include "sim/config/config_error.h"
#include "sim/runner/build_id.h"
#include "sim/runner/metrics.h"
#include "sim/runner/run_directory.h"
#include "sim/runner/text_file.h"

namespace plywood::eval {
namespace {

namespace fs = std::filesystem;

// metrics.json flattened to dotted keys; numbers as their shortest round-trip text.
struct RunMetrics {
  std::map<std::string, std::string> text;
  std::map<std::string, double> numbers;
};

void Flatten(const nlohmann::json& node, const std::string& prefix, RunMetrics& out) {
  if (node.is_object()) {
    for (auto it = node.begin(); it != node.end(); ++it)
      Flatten(it.value(), prefix.empty() ? it.key() : prefix + "." + it.key(), out);
    return;
  }
  if (node.is_number()) {
    const double value = node.get<double>();
    // A whole number as the run wrote it: run.seed above 2^53 came out as the nearest double. A
    // number the run wrote from a double reads back as the same text either way.
    out.text[prefix] = node.is_number_integer() ? node.dump() : sim::FormatNumber(value);
    out.numbers[prefix] = value;
  } else if (node.is_string()) {
    out.text[prefix] = node.get<std::string>();
  } else if (node.is_boolean()) {
    out.text[prefix] = node.get<bool>() ? "true" : "false";
  } else {
    out.text[prefix] = "";  // null: a number JSON cannot hold (NaN)
  }
}

RunMetrics ReadRunMetrics(const fs::path& file) {
  RunMetrics metrics;
  try {
    Flatten(nlohmann::json::parse(sim::ReadTextFile(file)), "", metrics);
  } catch (const nlohmann::json::exception& e) {
    throw sim::ConfigError(file.string(), "", std::string("not valid JSON: ") + e.what());
  }
  return metrics;
}

std::string Fixed(double value, const char* format) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

// Each file is written whole (WriteTextFile renames it into place), but the set is written one
// file after another: a collect killed after results.csv, or stopped by an error there ("'m' is
// in no run's metrics.json"), or whose plotting failed, left the previous collect's summary.csv
// and plots beside the new results.csv, as if they summarised it. They go first; a collect that
// does not finish leaves fewer files, never older ones.
void RemoveCollectedFiles(const fs::path& out_dir) {
  for (const char* name : {"summary.csv", "failures.csv", "results.csv"}) {
    std::error_code error;
    fs::remove(out_dir / name, error);
    if (error) {
      throw sim::ConfigError((out_dir / name).string(), "",
                             "cannot remove the previous collect's file: " + error.message());
    }
  }
  std::error_code error;
  const fs::path plots = out_dir / "plots";
  if (!fs::is_directory(plots, error)) return;
  for (const auto& entry : fs::directory_iterator(plots, error)) {
    if (entry.path().extension() != ".png") continue;
    std::error_code removed;
    fs::remove(entry.path(), removed);
    if (removed) {
      throw sim::ConfigError(entry.path().string(), "",
                             "cannot remove the previous collect's plot: " + removed.message());
    }
  }
}

}  // namespace

double StudentT95(int dof) {
  static const double kTable[] = {0,     12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365,
                                  2.306, 2.262,  2.228, 2.201, 2.179, 2.160, 2.145, 2.131,
                                  2.120, 2.110,  2.101, 2.093, 2.086, 2.080, 2.074, 2.069,
                                  2.064, 2.060,  2.056, 2.052, 2.048, 2.045, 2.042};
  if (dof <= 0) return 0.0;
  if (dof <= 30) return kTable[dof];
  // Beyond 30 the quantile is nearly linear in 1/dof: 2.042 at 30, 1.95996 at infinity.
  return 1.95996 + (2.042 - 1.95996) * 30.0 / dof;
}

SampleSummary Summarise(const std::vector<double>& values) {
  SampleSummary s;
  s.n = static_cast<int>(values.size());
  if (s.n == 0) return s;
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  s.min = sorted.front();
  s.max = sorted.back();
  s.p90 = sorted[(9 * sorted.size() + 9) / 10 - 1];  // ceil(0.9 n) in integers
  double sum = 0.0;
  for (double v : values) sum += v;
  s.mean = sum / s.n;
  // One run has no sample spread (n - 1 = 0) and no interval (Student's t with 0 degrees of
  // freedom is unbounded): both were written as 0 and [mean, mean], a certainty no single run
  // gives, exit 0 (s49). NaN: summary.csv leaves them empty, as it does with no run.
  if (s.n == 1) {
    s.std = s.ci95_low = s.ci95_high = std::numeric_limits<double>::quiet_NaN();
    return s;
  }
  if (s.min == s.max) {  // identical runs (a noise-free profile): exactly no spread
    s.mean = s.ci95_low = s.ci95_high = s.min;
    return s;
  }
  double squares = 0.0;
  for (double v : values) squares += (v - s.mean) * (v - s.mean);
  s.std = std::sqrt(squares / (s.n - 1));
  const double half = StudentT95(s.n - 1) * s.std / std::sqrt(s.n);
  s.ci95_low = s.mean - half;
  s.ci95_high = s.mean + half;
  return s;
}

SweepCollectOutcome CollectSweep(const fs::path& out_dir) {
  const fs::path manifest = out_dir / "cells.csv";
  const fs::path meta_file = out_dir / "sweep.json";
  if (!fs::is_regular_file(manifest) || !fs::is_regular_file(meta_file)) {
    throw sim::ConfigError(out_dir.string(), "",
                           "not a sweep directory (no cells.csv / sweep.json)");
  }
  nlohmann::json meta;
  try {
    meta = nlohmann::json::parse(sim::ReadTextFile(meta_file));
  } catch (const nlohmann::json::exception& e) {
    throw sim::ConfigError(meta_file.string(), "", std::string("not valid JSON: ") + e.what());
  }
  if (const auto damage = FindSweepMetaDamage(meta)) {
    throw sim::ConfigError(meta_file.string(), damage->field, damage->what);
  }
  RemoveCollectedFiles(out_dir);
  const std::string sweep_build = meta.value("plywood_build_id", std::string());
  const auto axes = meta.value("axes", std::vector<std::string>{});
  auto chosen = meta.value("metrics", std::vector<std::string>{});
  const bool print_table = !chosen.empty();  // hundreds of metrics would drown the screen
  const auto group_by = meta.value("group_by", std::vector<std::string>{});
  const bool several_experiments = meta.value("experiments", std::vector<std::string>{}).size() > 1;
  const bool profiles = meta.value("profiles", false);
  const auto rows = ParseCsv(sim::ReadTextFile(manifest));
  if (rows.empty() || rows[0].size() != 7 + axes.size()) {
    throw sim::ConfigError(manifest.string(), "", "header does not match sweep.json's axes");
  }

  struct Row {
    std::vector<std::string> cell;  // id, world, family, seed, axes
    RunMetrics metrics;
  };
  std::vector<Row> finished;
  std::string failures_csv;
  {
    std::vector<std::string> header{"id", "experiment", "world", "family", "profile", "seed"};
    for (const auto& a : axes) header.push_back(a);
    header.push_back("exit_code");
    header.push_back("error");
    failures_csv = CsvLine(header);
  }
  SweepCollectOutcome outcome;
  std::set<std::string> metric_keys;
  // A manifest cut at a line's end (or a row deleted or repeated) lost or doubled cells:
  // results.csv and summary.csv left them out without a word, and "2 of 2 runs finished".
  const std::size_t expected_cells = meta.value("cells", std::size_t{0});
  if (meta.contains("cells") && rows.size() - 1 != expected_cells) {
    throw sim::ConfigError(
        manifest.string(), "",
        "lists " + std::to_string(rows.size() - 1) + " cells, sweep.json says " +
            std::to_string(expected_cells) +
            " (cut or edited?): run the sweep again (plywood sweep SWEEP --out " +
            out_dir.string() + "), which rewrites it and reruns nothing finished");
  }
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const auto& row = rows[r];
    if (row.size() != rows[0].size()) {
      throw sim::ConfigError(manifest.string(), "line " + std::to_string(r + 1),
                             "expected " + std::to_string(rows[0].size()) + " fields");
    }
    if (row[0] != std::to_string(r - 1)) {
      throw sim::ConfigError(manifest.string(), "line " + std::to_string(r + 1),
                             "index: expected " + std::to_string(r - 1) + ", got '" + row[0] +
                                 "' (cut or edited?): run the sweep again, which rewrites it");
    }
    ++outcome.cells;
    const std::string& id = row[1];
    std::vector<std::string> cell(row.begin() + 1, row.end());
    const fs::path run = out_dir / "runs" / id;
    const fs::path failure = out_dir / "failures" / (id + ".txt");
    // A run without its marker never counts, nor one another build made (sweep.json names the
    // build that ran the sweep; an old sweep.json without it accepts any).
    if (sim::WhyNotAFinishedRun(run).empty() &&
        (sweep_build.empty() || sim::RunBuildId(run) == sweep_build)) {
      Row done{cell, ReadRunMetrics(run / "metrics.json")};
      for (const auto& [key, text] : done.metrics.text) metric_keys.insert(key);
      finished.push_back(std::move(done));
      ++outcome.done;
    } else if (fs::is_regular_file(failure)) {
      std::istringstream lines(sim::ReadTextFile(failure));
      std::string code, error;
      std::getline(lines, code);
      std::getline(lines, error);
      cell.push_back(code);
      cell.push_back(error);
      failures_csv += CsvLine(cell);
      ++outcome.failed;
    } else {
      if (sim::WhyNotAFinishedRun(run).empty()) ++outcome.other_build;
      ++outcome.missing;
    }
  }

  // results.csv
  std::vector<std::string> header{"id", "experiment", "world", "family", "profile", "seed"};
  for (const auto& a : axes) header.push_back(a);
  for (const auto& k : metric_keys) header.push_back(k);
  std::string results = CsvLine(header);
  for (const Row& row : finished) {
    std::vector<std::string> fields = row.cell;
    for (const auto& k : metric_keys) {
      const auto it = row.metrics.text.find(k);
      fields.push_back(it == row.metrics.text.end() ? "" : it->second);
    }
    results += CsvLine(fields);
  }
  sim::WriteTextFile(out_dir / "results.csv", results);
  sim::WriteTextFile(out_dir / "failures.csv", failures_csv);
  if (!finished.empty()) {
    for (const std::string& metric : chosen) {
      if (metric_keys.count(metric)) continue;
      std::string near;  // keys sharing the first part, to show what exists
      const std::string head = metric.substr(0, metric.find('.') + 1);
      for (const auto& k : metric_keys) {
        if (k.starts_with(head) && std::count(near.begin(), near.end(), ',') < 4)
          near += (near.empty() ? "" : ", ") + k;
      }
      throw sim::ConfigError(meta.value("sweep_file", out_dir.string()), "metrics",
                             "'" + metric + "' is in no run's metrics.json" +
                                 (near.empty() ? std::string() : " (there are: " + near + ")"));
    }
    // Summarised and plotted as numbers: one the runs write as text (run.world,
    // exploration.end_reason) was summarised as `n 0` beside every run's value, and the plots
    // stopped on it with a Python traceback, exit 0 (s61). A null (NaN) is a number not defined.
    for (const std::string& metric : chosen) {
      for (const Row& row : finished) {
        const auto text = row.metrics.text.find(metric);
        if (text == row.metrics.text.end() || text->second.empty() ||
            row.metrics.numbers.count(metric) > 0)
          continue;
        throw sim::ConfigError(meta.value("sweep_file", out_dir.string()), "metrics",
                               "'" + metric + "' is not a number (run " + row.cell[0] +
                                   "'s metrics.json gives '" + text->second +
                                   "'): summary.csv and the plots take numbers; its values are "
                                   "in results.csv, so leave it out of metrics:");
      }
    }
  }

  // summary.csv: groups in order of first appearance.
  if (chosen.empty()) {
    for (const auto& k : metric_keys) {
      const bool numeric = std::any_of(finished.begin(), finished.end(), [&](const Row& r) {
        return r.metrics.numbers.count(k) > 0;
      });
      if (numeric) chosen.push_back(k);
    }
  }
  // Row::cell: id, experiment, world, family, profile, seed, axes...
  std::vector<std::string> group_columns;
  std::vector<std::size_t> group_index;
  const auto group = [&](const std::string& column, std::size_t index) {
    group_columns.push_back(column);
    group_index.push_back(index);
  };
  if (several_experiments) group("experiment", 1);
  for (const auto& g : group_by) group(g, g == "world" ? 2 : g == "family" ? 3 : 5);
  if (profiles) group("profile", 4);
  // An axis with one value (e.g. output.snapshot: [false]) splits nothing: it stays in
  // results.csv but does not label the groups.
  for (std::size_t a = 0; a < axes.size(); ++a) {
    std::set<std::string> values;
    for (std::size_t r = 1; r < rows.size(); ++r) values.insert(rows[r][7 + a]);
    if (values.size() > 1) group(axes[a], 6 + a);
  }
  // Files are labelled by their stem in the summary ("seed001_room_1"); results.csv keeps paths.
  // Two files of one stem (a/room.xml and b/room.xml) keep their paths: labelled alike, their
  // runs would be pooled into one group, one mean over two worlds.
  std::map<std::pair<std::size_t, std::string>, std::set<std::string>> files_of_stem;
  for (const Row& row : finished) {
    for (std::size_t i : {1, 2})
      files_of_stem[{i, fs::path(row.cell[i]).stem().string()}].insert(row.cell[i]);
  }
  const auto label = [&](std::size_t index, const std::string& value) {
    if (index != 1 && index != 2) return value;
    const std::string stem = fs::path(value).stem().string();
    return files_of_stem[{index, stem}].size() > 1 ? value : stem;
  };
  std::vector<std::vector<std::string>> groups;
  std::map<std::vector<std::string>, std::vector<const Row*>> members;
  for (const Row& row : finished) {
    std::vector<std::string> key;
    for (std::size_t i : group_index) key.push_back(label(i, row.cell[i]));
    if (!members.count(key)) groups.push_back(key);
    members[key].push_back(&row);
  }
  std::vector<std::string> summary_header = group_columns;
  for (const char* c : {"metric", "n", "mean", "std", "ci95_low", "ci95_high", "min", "max", "p90"})
    summary_header.push_back(c);
  std::string summary = CsvLine(summary_header);
  std::string table;
  for (const auto& metric : chosen) {
    table += "\n" + metric + "\n";
    for (const auto& group : groups) {
      std::vector<double> values;
      for (const Row* row : members[group]) {
        const auto it = row->metrics.numbers.find(metric);
        if (it != row->metrics.numbers.end() && std::isfinite(it->second))
          values.push_back(it->second);
      }
      const SampleSummary s = Summarise(values);
      std::vector<std::string> fields = group;
      fields.push_back(metric);
      fields.push_back(std::to_string(s.n));
      for (double v : {s.mean, s.std, s.ci95_low, s.ci95_high, s.min, s.max, s.p90})
        fields.push_back(s.n && std::isfinite(v) ? sim::FormatNumber(v) : "");
      summary += CsvLine(fields);
      std::string label;
      for (std::size_t i = 0; i < group.size(); ++i)
        label += (i ? ", " : "") + group_columns[i] + "=" + group[i];
      if (label.empty()) label = "all runs";
      table += "  " + label + ": n " + std::to_string(s.n);
      // Runs without a value (null: undefined there, as drift_percent of a robot that stood) are
      // said, not left to read as a figure of nothing or a mean of all the group's runs (s63).
      const std::size_t runs = members[group].size();
      if (s.n == 0) {
        table += " (no value in " + std::string(runs == 1 ? "its run" : "any of its runs") +
                 ": null or absent in metrics.json, docs/run_outputs.md)";
      } else if (static_cast<std::size_t>(s.n) < runs) {
        table += " (of " + std::to_string(runs) + " runs; " + std::to_string(runs - s.n) +
                 " without a value)";
      }
      if (s.n == 1) {
        table += ", value " + Fixed(s.mean, "%.4g") + " (one run: no spread or 95 % CI)";
      } else if (s.n) {
        table += ", mean " + Fixed(s.mean, "%.4g") + " (95 % CI " + Fixed(s.ci95_low, "%.4g") +
                 " .. " + Fixed(s.ci95_high, "%.4g") + "), std " + Fixed(s.std, "%.3g") + ", min " +
                 Fixed(s.min, "%.4g") + ", max " + Fixed(s.max, "%.4g") + ", p90 " +
                 Fixed(s.p90, "%.4g");
      }
      table += "\n";
    }
  }
  sim::WriteTextFile(out_dir / "summary.csv", summary);
  if (print_table) {
    outcome.table = table;
  } else {
    outcome.table = "\nsummary.csv: " + std::to_string(chosen.size()) + " metrics x " +
                    std::to_string(groups.size()) +
                    " groups (name some under metrics: in the sweep to print and plot them)\n";
  }
  return outcome;
}

}  // namespace plywood::eval
