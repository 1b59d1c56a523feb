#pragma once

#include <mujoco/mujoco.h>

#include <array>

#include "sim/raycast/ray_caster.h"

namespace plywood::sim {

// The geom groups every sensor ray sees: all but Scene::kRobotGeomGroup, so a robot never sees
// itself (MJCF worlds use groups 0-2 and 4-5 freely).
std::array<mjtByte, mjNGROUP> RayGeomGroups();

// True when mj_ray(..., RayGeomGroups().data(), flg_static = 1, bodyexclude = -1, ...) would test
// this geom at all: its group is seen, and it is not fully transparent (MuJoCo's mj_ray skips
// geoms whose rgba, or material rgba, has alpha 0).
bool IsRayVisibleGeom(const mjModel* model, int geom_id);

// The reference caster: MuJoCo's mj_ray, which tests every geom of the model for every ray
// (no broadphase in 2.2.2), so its cost grows linearly with the world's geom count.
// Exact for every geom type, moving bodies included. Thread-safe: Cast only reads `data`.
class MujocoRayCaster : public RayCaster {
 public:
  // `model` and `data` must outlive the caster; rays use data's current geom poses.
  MujocoRayCaster(const mjModel* model, const mjData* data);

  bool Cast(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W, double max_range_m,
            RayHit* hit) const override;
  bool CastWithoutNormal(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W,
                         double max_range_m, RayHit* hit) const override;

 private:
  const mjModel* model_;
  const mjData* data_;
  std::array<mjtByte, mjNGROUP> geom_groups_;
};

}  // namespace plywood::sim
