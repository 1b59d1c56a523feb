#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "perception/lines/line_extractor.h"
#include "perception/lines/round_object_filter.h"

namespace plywood::perception {

// Sequential RANSAC (Fischler & Bolles 1981) as seed 004 used it, with its defects fixed: each
// round samples `iterations` point pairs from the points not yet explained, keeps the line with
// most inliers within an absolute distance_threshold_m (seed 004: relative to scene size), stops
// when that falls below min_inliers, refits the inliers by total least squares and collects them
// again, cuts them into runs at gaps wider than max_gap_m (walls on one infinite line are
// separate segments, and two table legs are not bridged), keeps runs of at least min_points, and
// removes the round's inliers before the next round (seed 004 never did, finding duplicates).
// Works on unordered point sets (an accumulated cloud) as well as scans. Deterministic: the
// generator is seeded from `seed` on every call.
// 1000 times the default (2-point samples find a line holding 1 % of the points with 99 %
// confidence in 46,000): about 0.1 s per 361-beam scan; 2e9 made a run that never ended.
inline constexpr int kMaxRansacIterations = 100000;

struct RansacOptions {
  int iterations = 100;
  double distance_threshold_m = 0.03;
  int min_inliers = 8;
  double max_gap_m = 0.3;
  int min_points = 5;
  double min_length_m = 0.06;  // as split_and_merge: chords across a table leg are not walls
  int max_lines = 100;
  std::uint64_t seed = 4;
  // On an ordered scan (Extract): runs are also cut where neighbours along the line are not
  // neighbours in the scan or have an opening between them (SplitRunsInScan, with
  // breakpoints.max_missing_beams), and points on round objects are left out before the search
  // (RoundObjectPoints: breakpoint groups cut by the end-point fit at distance_threshold_m).
  BreakpointOptions breakpoints;
  RoundObjectOptions round_objects;

  void Validate() const;
};

class RansacExtractor final : public RoundObjectAwareExtractor {
 public:
  explicit RansacExtractor(const RansacOptions& options = {});
  std::string name() const override { return "ransac"; }
  // The same on bare points (e.g. a world-frame cloud); `inliers` (optional) receives each
  // segment's point indices.
  std::vector<LineSegment> ExtractFromPoints(
      std::span<const Eigen::Vector2d> points,
      std::vector<std::vector<int>>* inliers = nullptr) const;

 private:
  std::vector<LineSegment> Run(const ScanPoints& scan,
                               std::vector<CircleFeature>* circles) const override {
    return ExtractImpl(scan.points, scan.HasScanOrder() ? &scan : nullptr, nullptr, circles);
  }
  // `scan` (optional) gives the points' scan order (and with it the round-object stage, whose
  // circles go to `circles` when given).
  std::vector<LineSegment> ExtractImpl(std::span<const Eigen::Vector2d> points,
                                       const ScanPoints* scan,
                                       std::vector<std::vector<int>>* inliers,
                                       std::vector<CircleFeature>* circles) const;

  const RansacOptions options_;
};

}  // namespace plywood::perception
