#pragma once

#include <string>
#include <vector>

#include "perception/lines/line_extractor.h"
#include "perception/lines/round_object_filter.h"

namespace plywood::perception {

// Incremental (line tracking; Siadat et al. 1997, as compared by Nguyen et al. 2005): walk each
// breakpoint group in scan order, growing the current line while the next point lies within
// max_distance_m of its total-least-squares fit; otherwise close the line and start a new one at
// that point. A single point off the line whose successor is back on it is skipped as an outlier.
// Neighbouring lines of one group are merged when their union fits within max_distance_m; groups
// one circle explains better (columns, table legs) give no lines (round_object_filter.h).
struct IncrementalOptions {
  BreakpointOptions breakpoints;
  double max_distance_m = 0.04;
  int seed_points = 3;  // points taken before the first distance test
  // 6 cm: chords across a table leg (5 cm) are not walls.
  SegmentFilterOptions filter{.min_points = 5, .min_length_m = 0.06};
  RoundObjectOptions round_objects;

  void Validate() const;
};

class IncrementalExtractor final : public RoundObjectAwareExtractor {
 public:
  explicit IncrementalExtractor(const IncrementalOptions& options = {});
  std::string name() const override { return "incremental"; }

 private:
  std::vector<LineSegment> Run(const ScanPoints& scan,
                               std::vector<CircleFeature>* circles) const override;
  const IncrementalOptions options_;
};

}  // namespace plywood::perception
