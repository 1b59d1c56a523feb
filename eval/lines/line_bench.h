#pragma once

#include <string>
#include <vector>

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

// Scans per second (one core) of every line extractor on a fixed 361-beam LMS 200 scan of an
// L-shaped room with 1 cm range noise (plywood bench's line-extraction part).
LineExtractorBench MeasureLineExtractors(double seconds_per_extractor = 0.3);

}  // namespace plywood::eval
