#include "sim/sensors/planar_scan.h"

#include <Eigen/Geometry>
#include <numbers>

#include "msgs/angle_units.h"
#include "sim/sensors/planar_fan.h"

namespace plywood::sim {

PlanarScan::PlanarScan(const Scene& scene, const std::string& site_name, const std::string& sensor,
                       double angle_min_deg, double angle_increment_deg, int beam_count,
                       double range_max_m)
    : site_(RequireSensorSite(scene, site_name, sensor, range_max_m)),
      angle_min_rad_(angle_min_deg * kDegToRad),
      angle_increment_rad_(angle_increment_deg * kDegToRad),
      dirs_S_(PlanarDirections(EvenAnglesRad(angle_min_deg, angle_increment_deg, beam_count))),
      found_(std::make_unique<bool[]>(dirs_S_.size())) {}

void PlanarScan::Cast(const Scene& scene, const RayCaster& caster, double range_min_m,
                      double range_max_m, ScanMeasurement* out,
                      const std::vector<char>* see_through) const {
  const int n = beam_count();
  msgs::LaserScan& scan = out->scan;
  scan.time_s = scene.time_s();
  scan.angle_min_rad = angle_min_rad_;
  scan.angle_increment_rad = angle_increment_rad_;
  scan.range_min_m = range_min_m;
  scan.range_max_m = range_max_m;
  scan.X_RS = site_.X_RS;
  scan.ranges_m.resize(n);
  out->hit_geom_ids.resize(n);

  const Eigen::Isometry3d X_WS = scene.SitePoseInWorld(site_.id);
  const Eigen::Matrix3d R_WS = X_WS.linear();
  const Eigen::Vector3d p_WS = X_WS.translation();
  double* ranges_m = scan.ranges_m.data();
  int* geom_ids = out->hit_geom_ids.data();
  dirs_W_.resize(n);
  hits_.resize(n);
  for (int i = 0; i < n; ++i) dirs_W_[i] = R_WS * dirs_S_[i];
  // All beams share the origin: one fan (same hits as one CastWithoutNormal per beam).
  caster.CastFanWithoutNormal(p_WS, dirs_W_.data(), n, range_max_m, hits_.data(), found_.get());
  const auto seen = [&](const RayHit& h) {
    return see_through == nullptr || h.geom_id < 0 ||
           h.geom_id >= static_cast<int>(see_through->size()) || !(*see_through)[h.geom_id];
  };
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d& dir_W = dirs_W_[i];
    RayHit& hit = hits_[i];
    bool found = found_[i] && hit.distance_m < range_max_m;
    // Past see-through geoms: recast from just beyond each face (a box's far face comes next).
    for (int pass = 0; found && !seen(hit) && pass < 16; ++pass) {
      const double offset = hit.distance_m + 1e-6;
      found = caster.CastWithoutNormal(p_WS + offset * dir_W, dir_W, range_max_m - offset, &hit) &&
              offset + hit.distance_m < range_max_m;
      hit.distance_m += offset;
    }
    if (found && seen(hit)) {
      ranges_m[i] = hit.distance_m;
      geom_ids[i] = hit.geom_id;
    } else {
      ranges_m[i] = range_max_m;
      geom_ids[i] = -1;
    }
  }
}

}  // namespace plywood::sim
