#pragma once

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "perception/lines/line_segment.h"

namespace plywood::perception {

// Line-extraction scoring against ground truth, the one place the definitions live (design.md
// "Metrics: Lines", docs/lines.md). Nguyen et al. (IROS 2005) style, per scan, in the sensor frame:
// - A ground-truth segment is OBSERVABLE in a scan when at least min_observed_rays of the scan's
//   used rays (returns inside the range cut) hit it (the simulator's per-beam hit segment ids).
// - An extracted segment MATCHES a ground-truth face (MatchFace) when
//   (1) both its endpoints lie within max_endpoint_distance_m (at most 1 m) of the face's line,
//   (2) it has a length (ends more than 1e-12 m apart: a point has no direction) and its
//       direction is within max(max_alpha_diff_deg, direction_sigmas * sigma_theta) of the
//       face's, where sigma_theta = range_noise_sigma_m / sqrt(S) is the standard deviation of the
//       direction a least-squares fit gets from num_points points spread evenly over the
//       segment's length L with independent range noise, S = L^2 n (n + 1) / (12 (n - 1)) their
//       spread about the mean (2 points: sqrt(2) sigma / L), and
//   (3) at least min_overlap_fraction of its length, projected on the face, lies within it.
//   Endpoints, not the normal form's r: r is measured at the foot of the perpendicular from the
//   sensor, so for a short segment far from that foot a fixed r gate is a tight angle gate (the
//   lever arm of issue 13). Each extracted segment takes its best match (smallest
//   largest-endpoint-distance / max_endpoint_distance_m + |angle| / angle tolerance), preferring
//   faces the scan observed.
// - recall = matched observable ground-truth segments / observable ground-truth segments;
//   precision = matched extracted segments / extracted segments (a match with any ground-truth
//   segment counts, observable or not); sigma_r, sigma_alpha = root mean square of Nguyen et
//   al.'s d_r and d_alpha (normal forms, sensor frame) over matched extracted segments (about
//   zero, so a bias counts); points per line = used points / extracted segments.
struct LineScoringOptions {
  double max_endpoint_distance_m = 0.05;
  double max_alpha_diff_deg = 5.0;    // the direction tolerance of a long segment
  double range_noise_sigma_m = 0.01;  // the LMS 200's (seed 000); 0 leaves the 5 deg alone
  double direction_sigmas = 3.0;
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
  // RMS errors of the matched lines; NaN (no number) when no line matched.
  double SigmaRM() const;
  double SigmaAlphaDeg() const;
  // NaN (no number) when no line was extracted: 0 read as lines of no points (s63).
  double PointsPerLine() const {
    return extracted ? double(points) / extracted : std::numeric_limits<double>::quiet_NaN();
  }
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

// How an extracted segment lies against one ground-truth face it matches.
struct FaceMatch {
  double endpoint_distance_m = 0.0;  // the larger of the two endpoints' distances from the line
  double angle_rad = 0.0;            // between the two directions, in [0, pi/2]
  double angle_tolerance_rad = 0.0;  // what (2) allowed this segment
  double d_alpha_rad = 0.0;          // Nguyen et al.'s normal-form differences (sensor frame)
  double d_r_m = 0.0;
};

// The match rule above for one segment and one face (usable on its own, e.g. by a map scorer).
// Returns nothing when they do not match.
std::optional<FaceMatch> MatchFace(const LineSegment& segment, const TruthSegment& face,
                                   const LineScoringOptions& options);

// The direction tolerance (2) for a segment of `length_m` fitted to `num_points` points.
double DirectionToleranceRad(double length_m, int num_points, const LineScoringOptions& options);

// Index of the truth segment `segment` matches best, or -1.
int MatchSegment(const LineSegment& segment, std::span<const TruthSegment> truth,
                 const LineScoringOptions& options, double* d_alpha = nullptr,
                 double* d_r = nullptr);

}  // namespace plywood::perception
