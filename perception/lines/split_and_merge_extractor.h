#pragma once

#include <string>
#include <vector>

#include "perception/lines/line_extractor.h"
#include "perception/lines/round_object_filter.h"
#include "perception/lines/tls_line_fit.h"

namespace plywood::perception {

enum class LineFitMethod { kTotalLeastSquares, kModal };
const char* ToString(LineFitMethod method);
// @throws std::invalid_argument for anything but "tls" and "modal".
LineFitMethod ParseLineFitMethod(const std::string& text);

// Split-and-merge (iterative end-point fit; Duda & Hart 1973, seed 003, Nguyen et al. 2005):
// break the scan at breakpoints, split each group recursively at the point farthest from the
// chord between its ends while that point is farther than split_threshold_m, refit every piece in
// normal form, then merge neighbouring pieces of the same group whose union still fits a line
// within split_threshold_m. Two departures from common implementations: the split point stays in
// the data (it goes to the piece whose line it fits better, not dropped), and pieces are merged
// only inside a breakpoint group, never across a gap such as a doorway. Groups that one circle
// explains better than their lines (columns, table legs) give no lines (round_object_filter.h).
struct SplitAndMergeOptions {
  BreakpointOptions breakpoints;
  double split_threshold_m = 0.04;
  // A farthest point whose neighbours both lie within half the threshold is a single outlier:
  // it is left out of the fit instead of splitting the wall.
  bool skip_single_outliers = true;
  // A run of fewer than filter.min_points points (too few for a line of their own) that stands in
  // front of a wall and steps back to it on both sides -- a table leg a few cm from the wall -- is
  // left out the same way, instead of ending a piece whose chord it turns (end_point_fit.h).
  bool skip_short_runs = true;
  LineFitMethod fit = LineFitMethod::kTotalLeastSquares;
  ModalFitOptions modal;
  // 4 points as seed 000's Table 2; 6 cm: chords across a table leg (5 cm) are not walls.
  SegmentFilterOptions filter{.min_points = 4, .min_length_m = 0.06};
  RoundObjectOptions round_objects;

  // @throws std::invalid_argument starting with the field name.
  void Validate() const;
};

class SplitAndMergeExtractor final : public RoundObjectAwareExtractor {
 public:
  explicit SplitAndMergeExtractor(const SplitAndMergeOptions& options = {});
  std::string name() const override { return "split_and_merge"; }

 private:
  std::vector<LineSegment> Run(const ScanPoints& scan,
                               std::vector<CircleFeature>* circles) const override;
  const SplitAndMergeOptions options_;
};

}  // namespace plywood::perception
