#pragma once

#include <vector>

#include "perception/lines/line_extractor.h"
#include "perception/lines/ray_explanation.h"
#include "perception/logs/carmen_log.h"

namespace plywood::perception {

// A line extractor run over every scan of a log (plywood replay). Real logs have no ground-truth
// lines, so the score is how much of the data the lines explain (ray_explanation.h): valid rays
// are those with 0.05 m < r < M - 0.2 m, M the log's maximum range (PARAM front_laser_max, else
// the largest range in the log, which marks "no return").
struct ReplayResult {
  // One scan's figures, in log order (scans.csv): to compare two versions scan by scan.
  struct Scan {
    long valid_rays = 0;
    long explained = 0;
    int lines = 0;
  };

  RayExplanation rays;
  std::vector<Scan> per_scan;
  long scans = 0;
  long lines = 0;
  double extract_wall_s = 0.0;  // time spent in Extract (wall clock; never in metrics.json)
  // Every segment in the world frame, placed by the scan's logged laser pose.
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> segments_W;

  double RaysPerLine() const { return lines ? double(rays.rays) / lines : 0.0; }
  double LinesPerScan() const { return scans ? double(lines) / scans : 0.0; }
  double UsPerScan() const { return scans ? 1e6 * extract_wall_s / scans : 0.0; }
};

// @param keep_segments  fill segments_W (for the picture).
ReplayResult ReplayLog(const CarmenLog& log, const LineExtractor& extractor,
                       bool keep_segments = true);

}  // namespace plywood::perception
