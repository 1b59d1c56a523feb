#pragma once

#include <filesystem>
#include <vector>

#include "eval/lines/line_scan_scorer.h"
#include "sim/config/lines_config.h"

namespace plywood::eval {

// Every laser scan of a finished single run as the `lines:` scorer saw it, rebuilt from the run
// directory: config.yaml (the lines: section's range cut and scoring gate), walls.csv,
// laser_scans.csv (the scans and true sensor poses at full precision) and laser_hits.csv. The same
// doubles as in the run, so scoring the same segments gives the same figures.
struct RunLaserScans {
  sim::LinesConfig lines;
  std::vector<TruthScan> scans;
};

// @throws sim::ConfigError naming the file (line, field) that is missing or does not fit.
RunLaserScans LoadRunLaserScans(const std::filesystem::path& run_dir);

}  // namespace plywood::eval
