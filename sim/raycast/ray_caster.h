#pragma once

#include <Eigen/Core>

namespace plywood::sim {

// What a ray hit: distance along the (unit) direction, the MuJoCo geom, and the outward surface
// normal at the hit point in the world frame (sonar needs the incidence angle).
struct RayHit {
  double distance_m = 0.0;
  int geom_id = -1;
  Eigen::Vector3d normal_W = Eigen::Vector3d::Zero();
};

// Casts rays against the world's geometry, never against the robot itself.
// Implementations: MujocoRayCaster (mj_ray, exact for anything) and GridRayCaster2D (a uniform
// grid over upright static geoms, exact for horizontal rays; falls back to mj_ray otherwise).
class RayCaster {
 public:
  virtual ~RayCaster() = default;

  // Casts from origin_W along unit direction dir_W. Returns false when nothing is hit within
  // max_range_m; otherwise fills `hit`.
  virtual bool Cast(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W,
                    double max_range_m, RayHit* hit) const = 0;

  // As Cast, but hit->normal_W is left as it was: for callers that read only the distance and the
  // geom (laser and IR scans), so that casters can skip the normal's work. Same distance and geom.
  virtual bool CastWithoutNormal(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W,
                                 double max_range_m, RayHit* hit) const {
    return Cast(origin_W, dir_W, max_range_m, hit);
  }

  // Casts `count` rays, ray i from origins_W[i] along dirs_W[i] (a scan's beams, a sonar ring's
  // cones): found[i] and hits[i] are exactly what Cast (with_normal) or CastWithoutNormal returns
  // and fills for that ray (hits[i] is left as it was where found[i] is false). Casters may share
  // set-up work between the rays; it pays when the origins lie close together.
  virtual void CastBatch(const Eigen::Vector3d* origins_W, const Eigen::Vector3d* dirs_W, int count,
                         double max_range_m, bool with_normal, RayHit* hits, bool* found) const {
    for (int i = 0; i < count; ++i) {
      found[i] = with_normal ? Cast(origins_W[i], dirs_W[i], max_range_m, &hits[i])
                             : CastWithoutNormal(origins_W[i], dirs_W[i], max_range_m, &hits[i]);
    }
  }

  // CastBatch without normals for rays that all start at origin_W (a scan's beams).
  virtual void CastFanWithoutNormal(const Eigen::Vector3d& origin_W, const Eigen::Vector3d* dirs_W,
                                    int count, double max_range_m, RayHit* hits,
                                    bool* found) const {
    for (int i = 0; i < count; ++i) {
      found[i] = CastWithoutNormal(origin_W, dirs_W[i], max_range_m, &hits[i]);
    }
  }
};

}  // namespace plywood::sim
