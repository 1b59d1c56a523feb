#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <vector>

#include "perception/sonar_map/partition_map.h"

namespace plywood::perception {

// Seed 001 models an obstacle by going round it: approach it, follow each boundary at the wall
// distance to its end, turn onto the next one, until the first boundary comes round again; each
// corner is the intersection of two consecutive boundary lines. These are that circuit's geometry.

// The corners of `box` grown by `distance` on every side, in the order a robot keeping the box on
// its left meets them (counter-clockwise), starting with the one nearest `from`. Driving from each
// to the next keeps the robot `distance` from the side between them.
std::vector<Eigen::Vector2d> CircuitAround(const Rect& box, double distance,
                                           const Eigen::Vector2d& from);

// A straight boundary line through `point` along the unit vector `direction`.
struct BoundaryLine {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();
};

// Intersection of two boundary lines; nullopt when they are (nearly) parallel.
std::optional<Eigen::Vector2d> Intersect(const BoundaryLine& a, const BoundaryLine& b);

// An obstacle outline from the occupied points heard round it: per column the lowest point gives
// the south boundary, the highest the north one, per row the westmost and eastmost the west and
// east ones (the seed's boundary: the occupied cells nearest the robot, one per row or column);
// each side is a chi-square line fit (sigma per point), dropping the farthest point while it
// lies more than two cells off the line (a row whose near face went unheard gives the far face),
// and the corners are the intersections of consecutive lines, south-west first, counter-clockwise.
struct ObstacleOutline {
  std::array<BoundaryLine, 4> sides;       // south, east, north, west
  std::array<Eigen::Vector2d, 4> corners;  // SW, SE, NE, NW
  Rect Box() const;                        // the axis-aligned box spanning the corners
};

// `points`: occupied cell centres of one obstacle; `cell_m` groups them into rows and columns
// (points within half a cell of the same row or column share it). A side needs at least
// `min_points` rows (columns); nullopt otherwise, when consecutive lines do not meet, or when
// opposite sides lie less than a cell apart (a face never heard).
std::optional<ObstacleOutline> OutlineFromBoundary(const std::vector<Eigen::Vector2d>& points,
                                                   double cell_m, double sigma_m, int min_points);

}  // namespace plywood::perception
