#pragma once

#include <Eigen/Core>
#include <vector>

#include "sim/world/generator/generated_world.h"

namespace plywood::sim::worldgen {

// The frame of one outline edge: u along it from its start corner, v outward (away from the room,
// on the edge's right). The edge's wall occupies 0 <= v <= kWallThicknessM.
struct EdgeFrame {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
  Eigen::Vector2d along = Eigen::Vector2d::UnitX();
  Eigen::Vector2d outward = -Eigen::Vector2d::UnitY();
  double length_m = 0.0;

  Eigen::Vector2d At(double u, double v) const { return start + u * along + v * outward; }
  // Edge `edge` of a counter-clockwise outline.
  static EdgeFrame Of(const std::vector<Eigen::Vector2d>& outline, int edge);
};

// A closed alcove behind the stretch [from_m, to_m] of an edge: three plywood walls standing on
// the edge wall's outer face and enclosing `depth_m` of floor behind it. Added only when its walls
// keep `gap_m` from every geom except the edge's own wall pieces (`edge_geoms`) and it covers no
// interior; returns whether it was added. Its outline joins world.interiors.
bool AddAlcove(GeneratedWorld& world, const EdgeFrame& edge, double from_m, double to_m,
               double depth_m, const std::vector<int>& edge_geoms, double gap_m);

// A free-standing plywood panel parallel to the edge, `distance_m` beyond the edge wall's outer
// face, spanning [from_m, to_m] along it (its face toward the room is the panel's inner face).
// Added under the same conditions as AddAlcove.
bool AddPanel(GeneratedWorld& world, const EdgeFrame& edge, double from_m, double to_m,
              double distance_m, double gap_m);

}  // namespace plywood::sim::worldgen
