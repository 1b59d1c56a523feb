#pragma once

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <vector>

namespace plywood::sim {

// A convex vertical edge of the static world (a box's corner, a wall's end), the target the sonar
// hears by diffraction (SonarOptions::edge_echoes): where it stands on the floor plane and the
// heights it spans.
struct ConvexEdge {
  Eigen::Vector2d point_W = Eigen::Vector2d::Zero();
  double z_min_m = 0.0;
  double z_max_m = 0.0;
};

// The four vertical edges of every static upright box of `model` (ExtractUprightGeoms, the
// robot's geoms excluded) that stand free: an edge whose outside, kBuriedProbeM out along the
// bisector of its two faces, lies inside another static upright geom of overlapping height (a box
// corner flush against a wall, the joint of two boxes written end to end, a wall's end inside the
// wall it meets) is no convex edge there and is left out. In geom order, then the box's corners
// counter-clockwise from (+x, +y) of its own axes.
std::vector<ConvexEdge> ExposedBoxEdges(const mjModel* model);

// Below the Polaroid 6500's wavelength (6.9 mm at 49.4 kHz in air at 20 C): a gap that narrow
// does not separate two reflectors.
inline constexpr double kBuriedProbeM = 0.005;

}  // namespace plywood::sim
