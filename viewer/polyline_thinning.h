#pragma once

#include <Eigen/Core>
#include <vector>

namespace plywood::viewer {

// The vertices of `points` to draw so that the drawn polyline stays within `tolerance_m` of every
// point (Reumann-Witkam, one pass): a straight stretch becomes one segment, a corner keeps its
// vertex. Every MuJoCo overlay line is a draw call of its own, and a long run's paths hold tens of
// thousands of samples; thinned at a few millimetres (below a pixel at any useful zoom) they cost
// hundreds. The first and last points are always kept.
std::vector<Eigen::Vector2d> ThinPolyline(const std::vector<Eigen::Vector2d>& points,
                                          double tolerance_m);

}  // namespace plywood::viewer
