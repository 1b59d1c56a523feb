#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "perception/logs/log_replay.h"

namespace plywood::eval {

// What `plywood replay` is asked to do.
struct LogReplayRequest {
  std::filesystem::path log;  // CARMEN log, plain or .gz
  std::string extractor = "split_and_merge";
  // Extractor options as in an experiment's `lines:` section: "split_and_merge.min_points=5".
  std::vector<std::string> overrides;
  bool skip_bad = false;          // skip and count malformed log lines instead of failing
  std::filesystem::path out_dir;  // empty: DefaultReplayDirectory(log, extractor)
  bool force = false;             // replace an earlier run in out_dir (sim::StagedRunDirectory)
};

// What the replay found, for printing; the same figures are in DIR/metrics.json.
struct LogReplaySummary {
  std::filesystem::path out_dir;
  std::size_t skipped_lines = 0;
  perception::ReplayResult result;
};

// runs/replay-LOGFILENAME-EXTRACTOR
std::filesystem::path DefaultReplayDirectory(const std::filesystem::path& log,
                                             const std::string& extractor);

// Runs the extractor on every scan of the log and scores it (perception::ReplayLog): writes
// DIR/config.yaml (the replay's log, extractor and resolved `lines:` options), metrics.json
// (replay.{extractor, scans, skipped_lines, valid_rays, lines, rays_explained, rms_m,
// rays_per_line, lines_per_scan, circles, circles_per_scan, rays_explained_with_circles,
// rms_with_circles_m}: deterministic figures only; rays_explained counts the lines alone),
// scans.csv (per scan in log order: valid rays, rays explained by the lines, lines, rays explained
// by lines or circles, circles; to compare two versions scan by scan), circles.csv (per circle:
// scan, centre and radius in the laser frame, RMS residual, points used), timing.json (wall
// clock) and segments.png (every segment placed by the log's poses), staged beside DIR and renamed
// into place with its completion marker last (sim::StagedRunDirectory). Every input is checked,
// then the output directory, before anything is extracted.
// @throws sim::ConfigError or std::invalid_argument (one line: exit code 2) for a bad option, an
// unknown extractor, a missing or malformed log or a refused output directory.
LogReplaySummary RunLogReplay(const LogReplayRequest& request);

}  // namespace plywood::eval
