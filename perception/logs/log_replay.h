#pragma once

#include <limits>
#include <vector>

#include "perception/lines/line_extractor.h"
#include "perception/lines/ray_explanation.h"
#include "perception/logs/carmen_log.h"

namespace plywood::perception {

// A line extractor run over every scan of a log (plywood replay). Real logs have no ground-truth
// lines, so the score is how much of the data the lines explain (ray_explanation.h): valid rays
// are those with 0.05 m < r < M - 0.2 m, M the log's maximum range (PARAM front_laser_max, else
// CARMEN's robot_front_laser_max, else the largest range in the log, which marks "no return"). Both
// figures are kept: rays explained by the lines alone, and by the lines or the round objects the
// extractor reported as circles.
struct ReplayResult {
  // One scan's figures, in log order (scans.csv): to compare two versions scan by scan.
  struct Scan {
    long valid_rays = 0;
    long explained = 0;               // by the lines
    long explained_with_circles = 0;  // by the lines or the circles
    int lines = 0;
    int circles = 0;
  };

  RayExplanation rays;               // explained by the lines alone
  RayExplanation rays_with_circles;  // by the lines or the reported circles (the acceptance's)
  std::vector<Scan> per_scan;
  long scans = 0;
  long lines = 0;
  long circles = 0;
  double extract_wall_s = 0.0;  // time spent in Extract (wall clock; never in metrics.json)
  // Every segment in the world frame, placed by the scan's logged laser pose.
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> segments_W;
  // Every circle: the scan it came from (log order) and the circle in the laser frame.
  std::vector<std::pair<long, CircleFeature>> circles_L;

  // NaN (no number) when no line was found, as PointsPerLine.
  double RaysPerLine() const {
    return lines ? double(rays.rays) / lines : std::numeric_limits<double>::quiet_NaN();
  }
  double LinesPerScan() const { return scans ? double(lines) / scans : 0.0; }
  double CirclesPerScan() const { return scans ? double(circles) / scans : 0.0; }
  double UsPerScan() const { return scans ? 1e6 * extract_wall_s / scans : 0.0; }
};

// The extractor's ExtractFeatures runs on every scan: lines and circles.
// @param keep_segments  fill segments_W (for the picture) and circles_L.
ReplayResult ReplayLog(const CarmenLog& log, const LineExtractor& extractor,
                       bool keep_segments = true);

}  // namespace plywood::perception
