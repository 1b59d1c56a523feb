#pragma once

#include <filesystem>
#include <string>

#include "eval/score/score_report.h"

namespace plywood::eval {

struct LinesScoreOptions {
  std::string name;  // the extractor when the file has no extractor column; default the file's stem
};

// `plywood score lines RUN_DIR FILE`: per-scan segments (eval/lines/lines_csv.h: scan, x1_m, y1_m,
// x2_m, y2_m in the sensor frame, optional extractor, alpha_rad, r_m, ...) scored against every
// scan of the run (eval/score/run_laser_scans.h) with the runner's scorer and its lines: options:
// lines.scans and lines.EXTRACTOR.{recall, precision, sigma_r_m, sigma_alpha_deg,
// points_per_line, lines_per_scan}. A scan without rows counts as a scan where nothing was found.
// @throws sim::ConfigError naming the file, line and field of anything wrong (a scan index beyond
// the run's scans among them).
ScoreReport ScoreLinesFile(const std::filesystem::path& run_dir, const std::filesystem::path& file,
                           const LinesScoreOptions& options = {});

}  // namespace plywood::eval
