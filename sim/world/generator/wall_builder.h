#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "sim/world/generator/generated_world.h"

namespace plywood::sim::worldgen {

// One edge of a room outline: built as plywood or left open, with openings (doorways) cut into it.
struct OutlineEdge {
  bool built = true;
  // [from, to] along the edge, metres from its start corner, sorted and disjoint.
  std::vector<std::pair<double, double>> openings;
};

// A straight plywood wall whose inner face runs from `a` to `b` (the room on the left), extended
// beyond `a` by `extend_a_m` and beyond `b` by `extend_b_m` along its own line.
WorldGeom& AddWallAlong(GeneratedWorld& world, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                        double extend_a_m = 0.0, double extend_b_m = 0.0);

// How far each of two walls meeting at a corner must reach past the corner along its inner face
// so that their outer faces meet: t / tan(phi / 2) for an interior angle phi below 180 deg (a
// convex corner: the boxes overlap in a mitre), 0 at a reflex corner (their boxes already meet).
// `turn_rad` is the outline's left turn at the corner (pi - phi).
double MitreExtensionM(double turn_rad);

// Walls along a closed outline given counter-clockwise (the room on the left of every edge), their
// inner faces exactly on the outline. Corners are mitred (MitreExtensionM) so any corner angle
// closes; a wall piece that ends at an opening or next to an unbuilt edge ends square at that
// point. edges.size() == outline.size(); edge i runs from outline[i] to outline[i + 1]. Returns the
// indices (into world.geoms) of the wall pieces built along each edge.
std::vector<std::vector<int>> AddOutlineWalls(GeneratedWorld& world,
                                              const std::vector<Eigen::Vector2d>& outline,
                                              const std::vector<OutlineEdge>& edges);

// Drops repeated and collinear corners of a closed outline.
std::vector<Eigen::Vector2d> SimplifyOutline(const std::vector<Eigen::Vector2d>& outline);

// Signed area (positive counter-clockwise).
double SignedArea(const std::vector<Eigen::Vector2d>& outline);

}  // namespace plywood::sim::worldgen
