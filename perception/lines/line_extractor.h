#pragma once

#include <span>
#include <string>
#include <vector>

#include "perception/lines/extracted_features.h"
#include "perception/lines/line_segment.h"
#include "perception/lines/scan_points.h"

namespace plywood::perception {

// A line extractor: scan points in, segments out, in the points' frame. Implementations are
// immutable after construction (options fixed), deterministic (a randomised one seeds its own
// generator per call from its options), and safe to call from several threads.
class LineExtractor {
 public:
  virtual ~LineExtractor() = default;
  virtual std::string name() const = 0;
  // An empty scan or one with too few points gives no segments; never throws on data.
  virtual std::vector<LineSegment> Extract(const ScanPoints& scan) const = 0;
  // The lines (the same as Extract's) and the round objects the extractor recognised as circles
  // (round_object_filter.h). An extractor without a round-object stage reports no circles.
  virtual ExtractedFeatures ExtractFeatures(const ScanPoints& scan) const {
    return {Extract(scan), {}};
  }
};

// An extractor with a round-object stage: one pass gives the lines and, when asked, the circles
// that stage removed, so Extract and ExtractFeatures cannot disagree on the lines.
class RoundObjectAwareExtractor : public LineExtractor {
 public:
  std::vector<LineSegment> Extract(const ScanPoints& scan) const final {
    return Run(scan, nullptr);
  }
  ExtractedFeatures ExtractFeatures(const ScanPoints& scan) const final {
    ExtractedFeatures out;
    out.lines = Run(scan, &out.circles);
    return out;
  }

 protected:
  // The lines of `scan`; the round objects removed on the way are added to `circles` unless null.
  virtual std::vector<LineSegment> Run(const ScanPoints& scan,
                                       std::vector<CircleFeature>* circles) const = 0;
};

// Breaking an ordered scan into groups of neighbouring points (shared by the ordered extractors).
// Two consecutive points belong to different groups when more than max_missing_beams beams
// between them gave no usable return (nothing was seen there: an opening seen past the range
// cut cannot be told from a wall, whatever its width -- the one break rule every extractor
// shares, see OpeningBetween), or when they are farther apart than
// min(max_m, max(min_m, r * sin(dphi) / sin(lambda - dphi) + 3 sigma)) -- the adaptive breakpoint
// of Borges & Aldon ("Line extraction in 2D range images for mobile robotics", JIRS 2004), kept
// below max_m so a doorway (0.8 m and wider) always breaks a wall.
struct BreakpointOptions {
  double min_m = 0.2;
  double max_m = 0.5;
  double lambda_deg = 10.0;
  double sigma_m = 0.01;
  // A single point far from both neighbours, whose neighbours are close to each other, is an
  // outlier (a dust speck, a mixed pixel): dropped instead of breaking the group.
  bool drop_lone_outliers = true;
  // 1: a single dropout (the LMS 200 drops ~0.2 % of its beams) does not cut a wall.
  int max_missing_beams = 1;

  void Validate() const;
};

// @throws std::invalid_argument("max_missing_beams: ...") when negative.
void ValidateMaxMissingBeams(int max_missing_beams);

// The shared break rule: whether more than max_missing_beams beams between point i and the next
// point j in scan order gave no usable return.
inline bool OpeningBetween(const ScanPoints& scan, int i, int j, int max_missing_beams) {
  return scan.MissingBeams(i, j) > max_missing_beams;
}

// Groups of point indices (each in scan order; for a closed scan a group may wrap past the end).
std::vector<std::vector<int>> SplitAtBreakpoints(const ScanPoints& scan,
                                                 const BreakpointOptions& options);

// Segments shorter than min_length_m or with fewer than min_points points are dropped.
struct SegmentFilterOptions {
  int min_points = 5;
  double min_length_m = 0.0;
};

// For extractors that find a line first and its points second (RANSAC, Hough): sorts
// points[indices] along the line with normal angle alpha_rad and cuts the sorted run wherever two
// neighbours are more than max_gap_m apart along it. Returns the runs, each sorted.
std::vector<std::vector<int>> SplitRunsAlongLine(std::span<const Eigen::Vector2d> points,
                                                 std::vector<int> indices, double alpha_rad,
                                                 double max_gap_m);

// The same on an ordered scan, where a line's points are also neighbours in scan order (a wall
// is seen at bearings that grow along it): runs are also cut where two neighbours along the line
// are more than one point apart in the scan (the run would bridge other things seen between
// them, e.g. where the infinite line crosses another wall) or have an opening between them
// (OpeningBetween).
std::vector<std::vector<int>> SplitRunsInScan(const ScanPoints& scan, std::vector<int> indices,
                                              double alpha_rad, double max_gap_m,
                                              int max_missing_beams);

}  // namespace plywood::perception
