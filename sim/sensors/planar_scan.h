#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "sim/raycast/ray_caster.h"
#include "sim/sensors/scan_measurement.h"
#include "sim/sensors/sensor_sites.h"
#include "sim/world/scene.h"

namespace plywood::sim {

// The geometry shared by the scanning range finders (laser, IR scanner): beam i leaves the origin
// of a robot site at angle_min_deg + i * angle_increment_deg from the site's x axis, in the site's
// x-y plane. Cast() gives the exact ranges; each sensor adds its own errors on top.
class PlanarScan {
 public:
  // `sensor` names the sensor in the error message ("the laser").
  // @throws ConfigError naming the robot file and the site when the robot has no such site, or
  // one that cannot hold a level scan reaching range_max_m (RequireSensorSite).
  PlanarScan(const Scene& scene, const std::string& site_name, const std::string& sensor,
             double angle_min_deg, double angle_increment_deg, int beam_count, double range_max_m);

  PlanarScan(const PlanarScan&) = delete;
  PlanarScan& operator=(const PlanarScan&) = delete;

  // Fills `out` at the scene's current state: stamp, beam angles, range limits, X_RS, and for each
  // beam the distance to the first hit closer than range_max_m with its geom id, or range_max_m
  // and -1 when there is none. Reuses out's buffers (no allocation after the first call).
  // `see_through` (by geom id; null: none) lists geoms the beam passes through, as an IR beam
  // passes a glass panel: the beam goes on from the far side of such a hit.
  void Cast(const Scene& scene, const RayCaster& caster, double range_min_m, double range_max_m,
            ScanMeasurement* out, const std::vector<char>* see_through = nullptr) const;

  const SensorSite& site() const { return site_; }
  int beam_count() const { return static_cast<int>(dirs_S_.size()); }

 private:
  const SensorSite site_;
  const double angle_min_rad_;
  const double angle_increment_rad_;
  const std::vector<Eigen::Vector3d> dirs_S_;  // unit beam directions in the site frame
  // Scratch of Cast (the beams' world directions and first hits), kept to avoid allocations.
  mutable std::vector<Eigen::Vector3d> dirs_W_;
  mutable std::vector<RayHit> hits_;
  std::unique_ptr<bool[]> found_;  // beam_count() flags
};

}  // namespace plywood::sim
