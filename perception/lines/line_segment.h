#pragma once

#include <Eigen/Core>

namespace plywood::perception {

// A 2-D line segment in normal form: the infinite line {p : p . (cos alpha, sin alpha) = r} with
// r >= 0 (alpha in (-pi, pi]) in the frame of the points it was fitted to, plus the stretch of it
// the points cover. Endpoints are the projections of the extreme points onto the line.
struct LineSegment {
  double alpha_rad = 0.0;
  double r_m = 0.0;
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
  Eigen::Vector2d end = Eigen::Vector2d::Zero();
  int num_points = 0;
  // Covariance of (alpha, r) from the total-least-squares fit (Pfister et al., "Weighted line
  // fitting algorithms for mobile robot map building", ICRA 2003, with equal point weights and
  // the residual variance as the point variance). Zero for noise-free points.
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
  // Index range [first_index, last_index] of the points in the scan order, when the extractor
  // works on ordered scans (-1 otherwise).
  int first_index = -1;
  int last_index = -1;

  Eigen::Vector2d Normal() const;
  double LengthM() const { return (end - start).norm(); }
  // Signed distance of `p` from the infinite line (positive on the far side from the origin).
  double SignedLineDistance(const Eigen::Vector2d& p) const { return p.dot(Normal()) - r_m; }
  // Euclidean distance of `p` from the segment (not from the infinite line).
  double SegmentDistance(const Eigen::Vector2d& p) const;
};

// The bounds a segment given from outside is held to, the same wherever it comes from (a
// lines.csv read back, a file `plywood score lines` scores, a plug-in extractor's output): its
// line (alpha_rad, r_m) passes within kMaxLineToEndsM of its own ends, and each end lies within
// kMaxEndToScanPointM of a point of the scan it was fitted to (the built-in extractors: under 3 cm;
// half a metre, ten times the scorer's 5 cm gate, tells a segment written in another frame).
inline constexpr double kMaxLineToEndsM = 1e-3;
inline constexpr double kMaxEndToScanPointM = 0.5;

// Normal form (alpha, r >= 0) of the line through `point` with unit normal (cos a, sin a):
// flips the normal when needed so r is not negative, and wraps alpha to (-pi, pi].
void CanonicalNormalForm(double a_rad, double signed_r_m, double* alpha_rad, double* r_m);

// |alpha_1 - alpha_2| wrapped to [0, pi].
double AngleDifferenceRad(double alpha_1_rad, double alpha_2_rad);

}  // namespace plywood::perception
