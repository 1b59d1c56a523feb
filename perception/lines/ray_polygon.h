#pragma once

#include <Eigen/Core>
#include <span>

namespace plywood::perception {

// Distance along the ray from the origin in unit direction `direction` to the nearest edge of the
// closed polygon `corners` (each corner joined to the next, the last to the first), or `nearest_m`
// when no edge is hit nearer. Exact ray casting for hand-made test scans and the bench scan.
double RayToPolygonM(const Eigen::Vector2d& direction, std::span<const Eigen::Vector2d> corners,
                     double nearest_m);

}  // namespace plywood::perception
