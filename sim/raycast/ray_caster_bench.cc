#include "sim/raycast/ray_caster_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "sim/raycast/grid_ray_caster_2d.h"
#include "sim/raycast/mujoco_ray_caster.h"

namespace plywood::sim {
namespace {

struct Ray {
  Eigen::Vector3d origin_W;
  Eigen::Vector3d dir_W;
};

// A point is inside some geom when a ray from it leaves a surface (outward normal along the ray).
bool IsFree(const RayCaster& caster, const Eigen::Vector3d& p_W) {
  for (const Eigen::Vector3d& dir : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)}) {
    RayHit hit;
    if (caster.Cast(p_W, dir, std::numeric_limits<double>::infinity(), &hit) &&
        hit.normal_W.dot(dir) > 0) {
      return false;
    }
  }
  return true;
}

// Seconds per ray of one pass over `rays`; the hits are kept so the work stays observable.
double TimePerRay(const RayCaster& caster, const std::vector<Ray>& rays, double max_range_m,
                  std::vector<RayHit>* hits, std::vector<char>* hit_flags) {
  const auto start = std::chrono::steady_clock::now();
  for (size_t i = 0; i < rays.size(); ++i) {
    (*hit_flags)[i] = caster.Cast(rays[i].origin_W, rays[i].dir_W, max_range_m, &(*hits)[i]);
  }
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  return elapsed.count() / std::max<size_t>(1, rays.size());
}

}  // namespace

RayCasterBenchResult RunRayCasterBench(const mjModel* model, const mjData* data, int rays,
                                       uint64_t seed, double max_range_m, double height_m) {
  RayCasterBenchResult result;
  double x_lo = std::numeric_limits<double>::infinity(), y_lo = x_lo;
  double x_hi = -x_lo, y_hi = -x_lo;
  for (int g = 0; g < model->ngeom; ++g) {
    if (!IsRayVisibleGeom(model, g)) continue;
    ++result.world_geoms;
    if (model->geom_type[g] == mjGEOM_PLANE) continue;
    if (model->body_weldid[model->geom_bodyid[g]] != 0) continue;
    const double r = model->geom_rbound[g];
    x_lo = std::min(x_lo, data->geom_xpos[3 * g] - r);
    x_hi = std::max(x_hi, data->geom_xpos[3 * g] + r);
    y_lo = std::min(y_lo, data->geom_xpos[3 * g + 1] - r);
    y_hi = std::max(y_hi, data->geom_xpos[3 * g + 1] + r);
  }
  if (!(x_lo < x_hi)) x_lo = y_lo = -5.0, x_hi = y_hi = 5.0;

  const MujocoRayCaster reference(model, data);
  const GridRayCaster2D grid(model, data);

  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(x_lo, x_hi), uy(y_lo, y_hi),
      yaw(-std::numbers::pi, std::numbers::pi);
  std::vector<Ray> samples(std::max(0, rays));
  for (Ray& ray : samples) {
    for (int attempt = 0; attempt < 1000; ++attempt) {
      ray.origin_W = Eigen::Vector3d(ux(rng), uy(rng), height_m);
      if (IsFree(reference, ray.origin_W)) break;
    }
    const double a = yaw(rng);
    ray.dir_W = Eigen::Vector3d(std::cos(a), std::sin(a), 0.0);
  }

  std::vector<RayHit> ref_hits(samples.size()), grid_hits(samples.size());
  std::vector<char> ref_flags(samples.size()), grid_flags(samples.size());
  result.mj_ray_us_per_ray =
      1e6 * TimePerRay(reference, samples, max_range_m, &ref_hits, &ref_flags);
  result.grid_us_per_ray = 1e6 * TimePerRay(grid, samples, max_range_m, &grid_hits, &grid_flags);
  for (size_t i = 0; i < samples.size(); ++i) {
    const bool same =
        ref_flags[i] == grid_flags[i] &&
        (!ref_flags[i] || (ref_hits[i].geom_id == grid_hits[i].geom_id &&
                           std::abs(ref_hits[i].distance_m - grid_hits[i].distance_m) <=
                               1e-9 * std::max(1.0, ref_hits[i].distance_m)));
    if (!same) ++result.mismatches;
  }
  return result;
}

}  // namespace plywood::sim
