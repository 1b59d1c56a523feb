#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace plywood::sim::worldgen {

// The z component of the 3-D cross product of two floor vectors: > 0 when `b` turns
// counter-clockwise from `a`.
inline double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// What a static geom covers on the floor, seen from above: a convex polygon (a box's four corners,
// counter-clockwise) or a disc (a cylinder).
struct Footprint {
  enum class Shape { kPolygon, kDisc };
  Shape shape = Shape::kPolygon;
  std::vector<Eigen::Vector2d> corners;              // polygons: convex, counter-clockwise
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // discs
  double radius_m = 0.0;                             // discs

  static Footprint Box(const Eigen::Vector2d& centre, const Eigen::Vector2d& half_size,
                       double yaw_rad);
  static Footprint Disc(const Eigen::Vector2d& centre, double radius_m);
};

// Distance from `p` to the footprint; 0 when `p` lies inside or on it.
double DistanceToPoint(const Footprint& f, const Eigen::Vector2d& p);

// Shortest distance between the two footprints; 0 when they touch or overlap.
double Distance(const Footprint& a, const Footprint& b);

// True when the open interiors intersect (more than touching by `tolerance_m`).
bool Overlap(const Footprint& a, const Footprint& b, double tolerance_m = 1e-9);

// Where the ray p + t * direction (unit direction, t >= 0) first meets the footprint's boundary,
// as t; nothing when it misses. A ray starting inside returns 0.
std::optional<double> RayHit(const Footprint& f, const Eigen::Vector2d& p,
                             const Eigen::Vector2d& direction);

// Even-odd point-in-polygon test for a simple polygon (any orientation).
bool InsidePolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p);

// Distance from `p` to the segment a-b.
double DistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b);

}  // namespace plywood::sim::worldgen
