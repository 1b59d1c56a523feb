#include "perception/lines/split_and_merge_extractor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "msgs/shortest_number.h"
#include "perception/lines/corner_refinement.h"
#include "perception/lines/end_point_fit.h"
#include "perception/lines/mixed_pixel_ends.h"
#include "perception/lines/round_past_range_cut.h"

namespace plywood::perception {

const char* ToString(LineFitMethod method) {
  return method == LineFitMethod::kModal ? "modal" : "tls";
}

LineFitMethod ParseLineFitMethod(const std::string& text) {
  if (text == "tls") return LineFitMethod::kTotalLeastSquares;
  if (text == "modal") return LineFitMethod::kModal;
  throw std::invalid_argument("expected tls or modal, got '" + text + "'");
}

void SplitAndMergeOptions::Validate() const {
  breakpoints.Validate();
  if (!(split_threshold_m > 0.0)) {
    throw std::invalid_argument("split_threshold_m: must be > 0, got " +
                                msgs::ShortestNumber(split_threshold_m));
  }
  modal.Validate();
  round_objects.Validate();
  if (filter.min_points < 2) {
    throw std::invalid_argument("min_points: must be >= 2, got " +
                                std::to_string(filter.min_points));
  }
  if (!(filter.min_length_m >= 0.0)) {
    throw std::invalid_argument("min_length_m: must be >= 0");
  }
}

SplitAndMergeExtractor::SplitAndMergeExtractor(const SplitAndMergeOptions& options)
    : options_(options) {
  options_.Validate();
}

std::vector<LineSegment> SplitAndMergeExtractor::Run(const ScanPoints& scan,
                                                     std::vector<CircleFeature>* circles) const {
  std::vector<LineSegment> out;
  const auto& p = scan.points;
  const double threshold = options_.split_threshold_m;
  const int min_points = std::max(2, options_.filter.min_points);
  // Runs of points too few for a line of their own, stepping off a wall and back (end_point_fit.h).
  const int max_outlier_run = options_.skip_short_runs ? min_points - 1 : 0;
  const auto fit = [&](std::span<const int> indices) {
    return options_.fit == LineFitMethod::kModal ? FitSegmentModal(p, indices, options_.modal)
                                                 : FitSegmentTls(p, indices);
  };
  // Each group's lines before their fit, in scan order (groups too small for a line give none).
  std::vector<std::vector<std::vector<int>>> group_lines;
  for (std::vector<int>& group : SplitAtBreakpoints(scan, options_.breakpoints)) {
    if (static_cast<int>(group.size()) < min_points) continue;
    std::vector<std::vector<int>> pieces =
        SplitByEndPointFit(p, group, threshold, options_.skip_single_outliers, max_outlier_run);
    // Round objects first: the merge below can join a column's chords into one line again (the
    // union's own fit is closer to the arc than the chord the split tested).
    RemoveRoundObjects(p, options_.breakpoints.sigma_m, options_.round_objects, &pieces, circles);
    // Merge neighbours whose union is still one line (the end-point fit over-splits when the
    // chord of a long group passes far from its middle).
    // The moments of merged.back(), its points added in order: adding a piece's points to a copy
    // gives the union's moments bit for bit as a fit of the union from scratch would.
    // merged_moments[k] is merged[k]'s, which the corner refinement below would sum again.
    std::vector<std::vector<int>> merged;
    std::vector<LineMoments> merged_moments;
    merged.reserve(pieces.size());
    merged_moments.reserve(pieces.size());
    for (auto& piece : pieces) {
      if (piece.size() < 2) continue;
      // The piece's own moments, summed in the same pass as the union's.
      LineMoments own;
      if (!merged.empty()) {
        LineMoments m = merged_moments.back();
        for (int i : piece) m.Add(p[i]), own.Add(p[i]);
        double alpha = 0, r = 0, c = 0, s = 0;
        m.FitWithNormal(&alpha, &r, &c, &s);
        // The new piece first: a failing merge usually fails there, before the long line.
        if (WithinLineDistance(p, piece, c, s, r, threshold) &&
            WithinLineDistance(p, merged.back(), c, s, r, threshold)) {
          merged.back().insert(merged.back().end(), piece.begin(), piece.end());
          merged_moments.back() = m;
          continue;
        }
      } else {
        for (int i : piece) own.Add(p[i]);
      }
      merged.push_back(std::move(piece));
      merged_moments.push_back(own);
    }
    // A closed scan without breakpoints is one group that starts and ends at the same corner: it
    // has no ends.
    const bool whole_scan = scan.closed && group.size() == p.size();
    // Mixed pixels at the group's two ends (mixed_pixel_ends.h), before the round test: a thin
    // leg's chord without them is a chord of the leg. A trimmed line's moments are summed again.
    if (!TrimGroupMixedPixelEnds(scan, options_.breakpoints, group, &merged).empty()) {
      for (std::size_t k : {std::size_t{0}, merged.size() - 1}) {
        merged_moments[k] = LineMoments();
        for (int i : merged[k]) merged_moments[k].Add(p[i]);
      }
    }
    // The lines are disjoint and keep their order: a kept line's first point finds its moments.
    std::vector<int> fronts(merged.size());
    for (std::size_t k = 0; k < merged.size(); ++k) fronts[k] = merged[k].front();
    RemoveRoundObjects(p, options_.breakpoints.sigma_m, options_.round_objects, &merged, circles);
    if (merged.size() != fronts.size()) {
      std::size_t from = 0;
      for (std::size_t k = 0; k < merged.size(); ++k, ++from) {
        while (fronts[from] != merged[k].front()) ++from;
        merged_moments[k] = merged_moments[from];
      }
      merged_moments.resize(merged.size());
    }
    RefineCorners(p, group, whole_scan, &merged, &merged_moments);
    // A round object whose flanks the range cut removed (round_past_range_cut.h).
    if (options_.round_objects.round_past_range_cut) {
      RemoveRoundObjectsPastRangeCut(scan, options_.breakpoints, threshold, options_.round_objects,
                                     group, &merged);
    }
    if (!merged.empty()) group_lines.push_back(std::move(merged));
  }
  if (options_.round_objects.join_across_occluders) {
    JoinRoundObjectsAcrossOccluders(scan, options_.breakpoints.sigma_m, options_.round_objects,
                                    &group_lines, circles);
  }
  for (const auto& lines : group_lines) {
    for (const auto& piece : lines) {
      if (static_cast<int>(piece.size()) < min_points) continue;
      LineSegment s = fit(piece);
      if (s.LengthM() < options_.filter.min_length_m) continue;
      out.push_back(s);
    }
  }
  return out;
}

}  // namespace plywood::perception
