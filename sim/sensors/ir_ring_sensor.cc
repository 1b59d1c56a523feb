#include "sim/sensors/ir_ring_sensor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "msgs/angle_units.h"
#include "sim/config/require_field.h"
#include "sim/sensors/noise_draws.h"
#include "sim/sensors/planar_fan.h"

namespace plywood::sim {

void IrRingOptions::Validate() const {
  RequireField(rays_per_beam >= 1 && rays_per_beam <= 100, "rays_per_beam", "must be in [1, 100]",
               rays_per_beam);
  RequireField(std::isfinite(beam_half_angle_deg) && beam_half_angle_deg >= 0.0 &&
                   beam_half_angle_deg < 90.0,
               "beam_half_angle_deg", "must be in [0, 90)", beam_half_angle_deg);
  RequireField(std::isfinite(incidence_limit_deg) && incidence_limit_deg >= 0.0 &&
                   incidence_limit_deg <= 90.0,
               "incidence_limit_deg", "must be in [0, 90]", incidence_limit_deg);
  RequireField(std::isfinite(range_max_m) && range_max_m > 0.0, "range_max_m", "must be > 0",
               range_max_m);
  RequireField(std::isfinite(range_min_m) && range_min_m >= 0.0 && range_min_m < range_max_m,
               "range_min_m", "must be in [0, range_max_m)", range_min_m);
  RequireField(std::isfinite(sigma_m) && sigma_m >= 0.0, "sigma_m", "must be >= 0", sigma_m);
  // As the laser's: a sigma beyond the whole range leaves no geometry in the readings.
  RequireField(sigma_m <= range_max_m, "sigma_m",
               "must be at most range_max_m (" + msgs::ShortestNumber(range_max_m) +
                   " m): a larger noise leaves no geometry in the readings",
               sigma_m);
  RequireField(std::isfinite(rate_hz) && rate_hz > 0.0, "rate_hz", "must be > 0", rate_hz);
}

std::vector<std::string> IrRingSensor::DefaultSiteNames() { return NumberedSiteNames("ir_", 16); }

IrRingSensor::IrRingSensor(const Scene& scene, const std::vector<std::string>& site_names,
                           const IrRingOptions& options, std::uint64_t seed)
    : options_((options.Validate(), options)),
      sites_(RequireSensorSites(scene, site_names, "the IR ring", options_.range_max_m)),
      rng_(seed) {
  dirs_S_ =
      PlanarDirections(SymmetricFanAnglesRad(options_.beam_half_angle_deg, options_.rays_per_beam));
  cos_incidence_limit_ = std::cos(options_.incidence_limit_deg * kDegToRad);
}

msgs::RangeRing IrRingSensor::Measure(const Scene& scene, const RayCaster& caster) {
  msgs::RangeRing out;
  Measure(scene, caster, &out);
  return out;
}

void IrRingSensor::Measure(const Scene& scene, const RayCaster& caster, msgs::RangeRing* out) {
  out->time_s = scene.time_s();
  out->range_min_m = options_.range_min_m;
  out->range_max_m = options_.range_max_m;
  out->readings.resize(sites_.size());
  NormalDraws noise;
  RayHit hit;
  for (std::size_t k = 0; k < sites_.size(); ++k) {
    const Eigen::Isometry3d X_WS = scene.SitePoseInWorld(sites_[k].id);
    const Eigen::Matrix3d R_WS = X_WS.linear();
    double range_m = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& dir_S : dirs_S_) {
      const Eigen::Vector3d dir_W = R_WS * dir_S;
      if (caster.Cast(X_WS.translation(), dir_W, options_.range_max_m, &hit) &&
          -dir_W.dot(hit.normal_W) >= cos_incidence_limit_) {
        range_m = std::min(range_m, hit.distance_m);
      }
    }
    if (std::isfinite(range_m) && !options_.noise_free && options_.sigma_m > 0.0) {
      range_m += noise(rng_, 0.0, options_.sigma_m);
    }
    msgs::RangeReading& reading = out->readings[k];
    reading.X_RS = sites_[k].X_RS;
    reading.echo = range_m < options_.range_max_m;
    reading.range_m = reading.echo ? std::max(range_m, options_.range_min_m) : 0.0;
  }
}

}  // namespace plywood::sim
