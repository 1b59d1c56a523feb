#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "perception/lines/line_segment.h"

namespace plywood::perception {

// Line-extraction scoring against ground truth, the one place the definitions live (design.md
// "Metrics: Lines", docs/lines.md). Nguyen et al. (IROS 2005) style, per scan, in the sensor frame:
// - A ground-truth segment is OBSERVABLE in a scan when at least min_observed_rays of the scan's
//   used rays (returns inside the range cut) hit it (the simulator's per-beam hit segment ids).
// - An extracted segment MATCHES a ground-truth segment when |d_alpha| <= max_alpha_diff_deg and
//   |d_r| <= max_r_diff_m between their normal forms (sensor frame), and at least
//   min_overlap_fraction of the extracted segment's length, projected on the ground-truth
//   segment, lies within it. Each extracted segment takes its best match (smallest
//   |d_alpha| / max_alpha + |d_r| / max_r), preferring segments the scan observed.
// - recall = matched observable ground-truth segments / observable ground-truth segments;
//   precision = matched extracted segments / extracted segments (a match with any ground-truth
//   segment counts, observable or not); sigma_r, sigma_alpha = root mean square of d_r and
//   d_alpha over matched extracted segments (about zero, so a bias counts); points per line =
//   used points / extracted segments.
struct LineScoringOptions {
  double max_alpha_diff_deg = 5.0;
  double max_r_diff_m = 0.05;
  double min_overlap_fraction = 0.5;
  int min_observed_rays = 5;

  void Validate() const;
};

// A ground-truth segment in the sensor frame with the number of used rays that hit it.
struct TruthSegment {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  int observed_rays = 0;
};

// Sums over scans; the ratios are computed by the accessors.
struct LineScore {
  long scans = 0;
  long observable = 0;
  long observable_matched = 0;
  long extracted = 0;
  long extracted_matched = 0;
  long points = 0;
  double sum_d_r_sq = 0.0;
  double sum_d_alpha_sq = 0.0;

  // 1 when there was nothing to find / nothing found (no evidence against the extractor).
  double Recall() const { return observable ? double(observable_matched) / observable : 1.0; }
  double Precision() const { return extracted ? double(extracted_matched) / extracted : 1.0; }
  double SigmaRM() const;
  double SigmaAlphaDeg() const;
  double PointsPerLine() const { return extracted ? double(points) / extracted : 0.0; }
  void Add(const LineScore& other);
};

// d_alpha (wrapped to (-pi, pi]) and d_r of line 1 minus line 2, taking line 2's other normal
// form (alpha + pi, -r) when that is closer in angle (lines near the origin).
void NormalFormDifference(double alpha_1, double r_1, double alpha_2, double r_2, double* d_alpha,
                          double* d_r);

// Scores one scan: `extracted` and `truth` in the same (sensor) frame, `used_points` the number of
// points the extractor was given.
LineScore ScoreScan(std::span<const LineSegment> extracted, std::span<const TruthSegment> truth,
                    long used_points, const LineScoringOptions& options = {});

// Index of the truth segment `segment` matches, or -1.
int MatchSegment(const LineSegment& segment, std::span<const TruthSegment> truth,
                 const LineScoringOptions& options, double* d_alpha = nullptr,
                 double* d_r = nullptr);

}  // namespace plywood::perception
