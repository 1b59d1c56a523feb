#pragma once

#include <Eigen/Core>
#include <limits>
#include <span>

namespace plywood::perception {

// How much a fitted piece of a scan bends, and how sure that is. A wall's points lie on a line; a
// column's (seed 003's small objects) lie on an arc that bulges towards the observer, and a short
// chord of it stays within a line fit's inlier distance (a 0.14 m chord of a 0.15 m radius column
// is 17 mm off its chord), so the line fit alone takes it for a wall.
struct PieceCurvature {
  // Curvature (1/m) of the quadratic v = a + b u + c u^2 fitted to the points in the frame of
  // their line (u along it, v away from the observer): 2c, positive when the points bulge towards
  // the observer (a convex object seen from outside); 1 / curvature is the implied radius.
  double curvature_per_m = 0.0;
  // Its standard error, from the fit's residuals but never below the one a range noise of
  // noise_floor_m gives (a few points can fit a parabola by chance); infinite: not known.
  double sigma_per_m = std::numeric_limits<double>::infinity();

  // Inverse-variance mean of two estimates of the same object's curvature (chords of one column
  // seen from several poses).
  PieceCurvature Combined(const PieceCurvature& other) const;
};

// Round small objects: a piece is one when its curvature is at least min_sigmas standard errors
// above zero (it does bend, towards the observer) and its implied radius is at most
// max_object_radius_m. Defaults are assumptions: 0.5 m is the line extractors' largest round
// object (round_object_filter.h; larger curves are walls, cut into chords), above the 0.3 m up to
// which geometric_map.cluster_recall expects a cylinder as a cluster, because the chords that
// reach the map are those one scan could not tell (their curvature estimates are the low ones: a
// 0.285 m column's merged chords imply 0.35-0.4 m); 3 sigmas accept one straight piece in 740 by
// chance, and then only if its implied radius is also that small; 5 mm is the IR scanner's range
// noise.
struct RoundPieceOptions {
  double max_object_radius_m = 0.5;
  double min_sigmas = 3.0;
  double noise_floor_m = 0.005;

  // @throws std::invalid_argument starting with the field's name.
  void Validate() const;

  bool IsRound(const PieceCurvature& c) const;
};

// The curvature of points[indices] (at least 3) about the line through `line_start`-`line_end`, as
// seen from `observer`.
PieceCurvature FitPieceCurvature(std::span<const Eigen::Vector2d> points,
                                 std::span<const int> indices, const Eigen::Vector2d& line_start,
                                 const Eigen::Vector2d& line_end, const Eigen::Vector2d& observer,
                                 double noise_floor_m);

}  // namespace plywood::perception
