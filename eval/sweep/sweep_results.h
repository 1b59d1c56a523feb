#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace plywood::eval {

// Mean, spread and the 95 % confidence interval of the mean (Student's t) of some values, and
// their 90th percentile (issue 14's bar is on it).
struct SampleSummary {
  int n = 0;
  double mean = 0.0;
  double std = 0.0;       // sample standard deviation (n - 1); NaN for n = 1 (undefined)
  double ci95_low = 0.0;  // NaN for n = 1: one run bounds no interval
  double ci95_high = 0.0;
  double min = 0.0;
  double max = 0.0;
  // Nearest rank: the smallest value at least 90 % of the values are no larger than (the
  // ceil(0.9 n)-th smallest), always one of the values, as docs/sonar_map.md's tables use.
  double p90 = 0.0;
};
SampleSummary Summarise(const std::vector<double>& values);

// Two-sided 95 % quantile of Student's t with `dof` degrees of freedom (exact table to 30, then
// interpolated in 1/dof towards 1.95996).
double StudentT95(int dof);

struct SweepCollectOutcome {
  int cells = 0;
  int done = 0;
  int failed = 0;
  int missing = 0;      // neither finished nor failed (not run yet, or another shard's)
  int other_build = 0;  // of `missing`: finished by another plywood build than the sweep's
  std::string table;    // the printed summary
};

// Reads a sweep directory (its cells.csv and sweep.json, every finished run's metrics.json and
// every failure) and writes, in the sweep's fixed cell order, so an interrupted and resumed sweep
// gives the same bytes as one that never stopped:
//   results.csv  one header line, one row per finished run: id, experiment, world, family,
//                profile, seed, every axis value, then every metric (union over runs, sorted;
//                empty where a run has none)
//   failures.csv one row per failed run: the same cell columns, exit_code, error
//   summary.csv  one row per group (experiment when there are several, group_by columns, profile,
//                the set axes' values) and metric: n,
//                mean, std, ci95_low, ci95_high, min, max, for the sweep's chosen metrics (all
//                numeric metrics when it chose none)
// Directories without a finished run never count. @throws sim::ConfigError when DIR is not a sweep.
SweepCollectOutcome CollectSweep(const std::filesystem::path& out_dir);

}  // namespace plywood::eval
