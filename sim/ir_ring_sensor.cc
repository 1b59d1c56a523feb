#include "sim/ir_ring_sensor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "sim/config_error.h"

namespace plywood::sim {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

void Require(bool ok, const std::string& field, const std::string& what, double value) {
  if (!ok) {
    throw std::invalid_argument(field + ": " + what + ", got " + std::to_string(value));
  }
}

}  // namespace

void IrRingOptions::Validate() const {
  Require(rays_per_beam >= 1 && rays_per_beam <= 100, "rays_per_beam", "must be in [1, 100]",
          rays_per_beam);
  Require(std::isfinite(beam_half_angle_deg) && beam_half_angle_deg >= 0.0 &&
              beam_half_angle_deg < 90.0,
          "beam_half_angle_deg", "must be in [0, 90)", beam_half_angle_deg);
  Require(std::isfinite(incidence_limit_deg) && incidence_limit_deg >= 0.0 &&
              incidence_limit_deg <= 90.0,
          "incidence_limit_deg", "must be in [0, 90]", incidence_limit_deg);
  Require(std::isfinite(range_max_m) && range_max_m > 0.0, "range_max_m", "must be > 0",
          range_max_m);
  Require(std::isfinite(range_min_m) && range_min_m >= 0.0 && range_min_m < range_max_m,
          "range_min_m", "must be in [0, range_max_m)", range_min_m);
  Require(std::isfinite(sigma_m) && sigma_m >= 0.0, "sigma_m", "must be >= 0", sigma_m);
  Require(std::isfinite(rate_hz) && rate_hz > 0.0, "rate_hz", "must be > 0", rate_hz);
}

std::vector<std::string> IrRingSensor::DefaultSiteNames() {
  std::vector<std::string> names;
  for (int i = 0; i < 16; ++i) names.push_back("ir_" + std::to_string(i));
  return names;
}

IrRingSensor::IrRingSensor(const Scene& scene, const std::vector<std::string>& site_names,
                           const IrRingOptions& options, std::uint64_t seed)
    : options_((options.Validate(), options)), rng_(seed) {
  if (site_names.empty()) throw std::invalid_argument("site_names: must not be empty");
  for (const std::string& name : site_names) {
    const std::optional<int> id = scene.FindSite(name);
    if (!id) throw ConfigError("robot", name, "no such site on the robot; the IR ring needs it");
    site_ids_.push_back(*id);
    X_RS_.push_back(scene.SitePoseInRobot(*id));
  }
  const int n = options_.rays_per_beam;
  for (int j = 0; j < n; ++j) {
    const double a = n == 1 ? 0.0
                            : options_.beam_half_angle_deg * kDegToRad *
                                  (-1.0 + 2.0 * j / static_cast<double>(n - 1));
    dirs_S_.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
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
  out->readings.resize(site_ids_.size());
  std::normal_distribution<double> noise(0.0, options_.sigma_m);
  RayHit hit;
  for (std::size_t k = 0; k < site_ids_.size(); ++k) {
    const Eigen::Isometry3d X_WS = scene.SitePoseInWorld(site_ids_[k]);
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
      range_m += noise(rng_);
    }
    msgs::RangeReading& reading = out->readings[k];
    reading.X_RS = X_RS_[k];
    reading.echo = range_m < options_.range_max_m;
    reading.range_m = reading.echo ? std::max(range_m, options_.range_min_m) : 0.0;
  }
}

}  // namespace plywood::sim
