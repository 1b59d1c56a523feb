#pragma once

#include <string>
#include <vector>

#include "msgs/laser_scan.h"

namespace plywood::eval {

// One line extractor's speed on the bench scan (wall clock, one core).
struct LineExtractorSpeed {
  std::string name;
  double scans_per_s = 0.0;
  double lines_per_scan = 0.0;
};

struct LineExtractorBench {
  std::size_t scan_points = 0;  // points of the bench scan
  std::vector<LineExtractorSpeed> extractors;
};

// The bench scan: 361 beams over 180 deg at 0.5 deg from (0, 0), facing +x, inside an L-shaped
// room, with 1 cm Gaussian range noise from a fixed seed (the same scan on every call).
msgs::LaserScan LineBenchScan();

// Scans per second (one core) of every line extractor on a fixed 361-beam LMS 200 scan of an
// L-shaped room with 1 cm range noise (plywood bench's line-extraction part).
LineExtractorBench MeasureLineExtractors(double seconds_per_extractor = 0.3);

}  // namespace plywood::eval
