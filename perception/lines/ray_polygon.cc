#include "perception/lines/ray_polygon.h"

#include <algorithm>
#include <cmath>

namespace plywood::perception {

double RayToPolygonM(const Eigen::Vector2d& direction, std::span<const Eigen::Vector2d> corners,
                     double nearest_m) {
  const Eigen::Vector2d& d = direction;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Eigen::Vector2d p = corners[k], e = corners[(k + 1) % corners.size()] - p;
    const double den = d.x() * e.y() - d.y() * e.x();
    if (std::abs(den) < 1e-12) continue;                     // parallel to the edge
    const double t = (p.x() * e.y() - p.y() * e.x()) / den;  // along the ray
    const double u = (p.x() * d.y() - p.y() * d.x()) / den;  // along the edge, 0..1 on it
    if (t > 0 && u >= 0 && u <= 1) nearest_m = std::min(nearest_m, t);
  }
  return nearest_m;
}

}  // namespace plywood::perception
