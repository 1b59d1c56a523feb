#include "sim/raycast/surface_normal.h"

#include <algorithm>
#include <cmath>

namespace plywood::sim {
namespace {

// Scales v (geom frame) to unit length and rotates it to the world; zero stays zero.
Eigen::Vector3d UnitToWorld(const mjtNum* R, double x, double y, double z) {
  const double n = std::sqrt(x * x + y * y + z * z);
  if (!(n > 0.0)) return Eigen::Vector3d::Zero();
  x /= n;
  y /= n;
  z /= n;
  return {R[0] * x + R[1] * y + R[2] * z, R[3] * x + R[4] * y + R[5] * z,
          R[6] * x + R[7] * y + R[8] * z};
}

}  // namespace

// Plain arrays rather than Eigen expressions: this runs once per ray hit and the grid caster's
// whole per-ray budget is a few dozen nanoseconds.
Eigen::Vector3d SurfaceNormal(const mjModel* model, const mjData* data, int geom_id,
                              const Eigen::Vector3d& p_W) {
  const mjtNum* x = data->geom_xpos + 3 * geom_id;
  // MuJoCo stores geom_xmat row-major with the geom's axes as columns: p_W = R * p_G + x.
  const mjtNum* R = data->geom_xmat + 9 * geom_id;
  const mjtNum* size = model->geom_size + 3 * geom_id;
  const double d0 = p_W.x() - x[0], d1 = p_W.y() - x[1], d2 = p_W.z() - x[2];
  const double p[3] = {R[0] * d0 + R[3] * d1 + R[6] * d2, R[1] * d0 + R[4] * d1 + R[7] * d2,
                       R[2] * d0 + R[5] * d1 + R[8] * d2};

  switch (model->geom_type[geom_id]) {
    case mjGEOM_PLANE:
      return {R[2], R[5], R[8]};
    case mjGEOM_BOX: {
      int face = 0;
      double best = std::abs(p[0]) / size[0];
      for (int i = 1; i < 3; ++i) {
        const double ratio = std::abs(p[i]) / size[i];
        if (ratio > best) {
          best = ratio;
          face = i;
        }
      }
      const double sign = p[face] >= 0.0 ? 1.0 : -1.0;
      return {sign * R[face], sign * R[3 + face], sign * R[6 + face]};
    }
    case mjGEOM_CYLINDER: {
      const double radial = std::sqrt(p[0] * p[0] + p[1] * p[1]);
      if (std::abs(p[2]) / size[1] > radial / size[0]) {
        const double sign = p[2] >= 0.0 ? 1.0 : -1.0;
        return {sign * R[2], sign * R[5], sign * R[8]};
      }
      return UnitToWorld(R, p[0], p[1], 0.0);
    }
    case mjGEOM_SPHERE:
      return UnitToWorld(R, p[0], p[1], p[2]);
    case mjGEOM_CAPSULE: {
      const double z_axis = std::clamp(p[2], -size[1], size[1]);
      return UnitToWorld(R, p[0], p[1], p[2] - z_axis);
    }
    case mjGEOM_ELLIPSOID:
      return UnitToWorld(R, p[0] / (size[0] * size[0]), p[1] / (size[1] * size[1]),
                         p[2] / (size[2] * size[2]));
    default:
      return Eigen::Vector3d::Zero();
  }
}

}  // namespace plywood::sim
