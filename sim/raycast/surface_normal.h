#pragma once

#include <mujoco/mujoco.h>

#include <Eigen/Core>

namespace plywood::sim {

// Outward unit normal, in the world frame, of geom `geom_id` at a point p_W on (or numerically
// near) its surface, from the geom's current pose in `data` (geom_xpos, geom_xmat).
//   box:       the face whose |p_i| / size_i is largest (p in the geom frame);
//   cylinder:  the cap or the round side, whichever the point is relatively closer to;
//   sphere:    radial; capsule: radial from the nearest point of the axis segment;
//   ellipsoid: the gradient of x^2/a^2 + y^2/b^2 + z^2/c^2 (exact on the surface);
//   plane:     the geom's local +z.
// Meshes and height fields are not supported: returns the zero vector, and callers substitute a
// head-on normal. A point at the very centre of a round geom also yields the zero vector.
Eigen::Vector3d SurfaceNormal(const mjModel* model, const mjData* data, int geom_id,
                              const Eigen::Vector3d& p_W);

}  // namespace plywood::sim
