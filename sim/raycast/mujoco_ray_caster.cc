#include "sim/raycast/mujoco_ray_caster.h"

#include <algorithm>

#include "sim/raycast/surface_normal.h"
#include "sim/world/scene.h"

namespace plywood::sim {

std::array<mjtByte, mjNGROUP> RayGeomGroups() {
  std::array<mjtByte, mjNGROUP> groups;
  groups.fill(1);
  groups[Scene::kRobotGeomGroup] = 0;
  return groups;
}

bool IsRayVisibleGeom(const mjModel* model, int geom_id) {
  // Mirrors mj_ray's elimination rules (engine_ray.c) for the mask above.
  const int material = model->geom_matid[geom_id];
  if (material < 0 && model->geom_rgba[4 * geom_id + 3] == 0) return false;
  if (material >= 0 && model->mat_rgba[4 * material + 3] == 0) return false;
  const int group = std::clamp(model->geom_group[geom_id], 0, mjNGROUP - 1);
  return RayGeomGroups()[group] != 0;
}

MujocoRayCaster::MujocoRayCaster(const mjModel* model, const mjData* data)
    : model_(model), data_(data), geom_groups_(RayGeomGroups()) {}

bool MujocoRayCaster::Cast(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W,
                           double max_range_m, RayHit* hit) const {
  if (!CastWithoutNormal(origin_W, dir_W, max_range_m, hit)) return false;
  hit->normal_W = SurfaceNormal(model_, data_, hit->geom_id, origin_W + hit->distance_m * dir_W);
  if (hit->normal_W.isZero()) hit->normal_W = -dir_W;  // meshes, height fields
  return true;
}

bool MujocoRayCaster::CastWithoutNormal(const Eigen::Vector3d& origin_W,
                                        const Eigen::Vector3d& dir_W, double max_range_m,
                                        RayHit* hit) const {
  int geom_id = -1;
  const mjtNum distance = mj_ray(model_, data_, origin_W.data(), dir_W.data(), geom_groups_.data(),
                                 /*flg_static=*/1, /*bodyexclude=*/-1, &geom_id);
  // mj_ray reports "no hit" as -1.
  if (geom_id < 0 || distance < 0 || distance > max_range_m) return false;
  hit->distance_m = distance;
  hit->geom_id = geom_id;
  return true;
}

}  // namespace plywood::sim
