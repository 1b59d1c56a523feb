#pragma once

#include <string>
#include <vector>

#include "perception/lines/line_extractor.h"

namespace lab {

// A plain line extractor, written from scratch for this example: cut the ordered scan wherever
// two neighbouring points are more than max_gap_m apart, split each run recursively at the point
// farthest from the chord between its ends while that point is farther than split_distance_m
// (iterative end-point fit, no merge step), and fit every piece by total least squares.
struct EndpointFitOptions {
  double max_gap_m = 0.2;
  double split_distance_m = 0.03;
  int min_points = 5;
  double min_length_m = 0.1;
};

class EndpointFitExtractor final : public plywood::perception::LineExtractor {
 public:
  explicit EndpointFitExtractor(const EndpointFitOptions& options) : options_(options) {}
  std::string name() const override { return "lab_endpoint_fit"; }
  std::vector<plywood::perception::LineSegment> Extract(
      const plywood::perception::ScanPoints& scan) const override;

 private:
  EndpointFitOptions options_;
};

}  // namespace lab
