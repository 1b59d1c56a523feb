#include "sim/ir_scanner_sensor.h"

#include <algorithm>
#include <cmath>
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

int RequireSite(const Scene& scene, const std::string& site_name) {
  const std::optional<int> id = scene.FindSite(site_name);
  if (!id) {
    throw ConfigError("robot", site_name, "no such site on the robot; the IR scanner needs it");
  }
  return *id;
}

}  // namespace

void IrScannerOptions::Validate() const {
  Require(std::isfinite(fov_deg) && fov_deg > 0.0 && fov_deg <= 360.0, "fov_deg",
          "must be in (0, 360]", fov_deg);
  Require(std::isfinite(resolution_deg) && resolution_deg > 0.0 && resolution_deg <= fov_deg,
          "resolution_deg", "must be in (0, fov_deg]", resolution_deg);
  const double steps = fov_deg / resolution_deg;
  Require(std::abs(steps - std::round(steps)) < 1e-9, "fov_deg",
          "must be a whole number of resolution_deg steps", fov_deg);
  Require(std::isfinite(range_max_m) && range_max_m > 0.0, "range_max_m", "must be > 0",
          range_max_m);
  Require(std::isfinite(range_min_m) && range_min_m >= 0.0 && range_min_m < range_max_m,
          "range_min_m", "must be in [0, range_max_m)", range_min_m);
  Require(std::isfinite(sigma_m) && sigma_m >= 0.0, "sigma_m", "must be >= 0", sigma_m);
  Require(outlier_probability >= 0.0 && outlier_probability <= 1.0, "outlier_probability",
          "must be in [0, 1]", outlier_probability);
  Require(std::isfinite(rate_hz) && rate_hz > 0.0, "rate_hz", "must be > 0", rate_hz);
}

int IrScannerOptions::BeamCount() const {
  const int steps = static_cast<int>(std::lround(fov_deg / resolution_deg));
  return std::abs(fov_deg - 360.0) < 1e-9 ? steps : steps + 1;
}

IrScannerSensor::IrScannerSensor(const Scene& scene, const std::string& site_name,
                                 const IrScannerOptions& options, std::uint64_t seed)
    : options_((options.Validate(), options)),
      site_id_(RequireSite(scene, site_name)),
      X_RS_(scene.SitePoseInRobot(site_id_)),
      rng_(seed) {
  const int n = options_.BeamCount();
  dirs_S_.reserve(n);
  for (int i = 0; i < n; ++i) {
    const double a = (-options_.fov_deg / 2.0 + i * options_.resolution_deg) * kDegToRad;
    dirs_S_.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
}

ScanMeasurement IrScannerSensor::Measure(const Scene& scene, const RayCaster& caster) {
  ScanMeasurement out;
  Measure(scene, caster, &out);
  return out;
}

void IrScannerSensor::Measure(const Scene& scene, const RayCaster& caster, ScanMeasurement* out) {
  const int n = static_cast<int>(dirs_S_.size());
  const double range_max_m = options_.range_max_m;
  msgs::LaserScan& scan = out->scan;
  scan.time_s = scene.time_s();
  scan.angle_min_rad = -options_.fov_deg / 2.0 * kDegToRad;
  scan.angle_increment_rad = options_.resolution_deg * kDegToRad;
  scan.range_min_m = options_.range_min_m;
  scan.range_max_m = range_max_m;
  scan.X_RS = X_RS_;
  scan.ranges_m.resize(n);
  out->hit_geom_ids.resize(n);

  const Eigen::Isometry3d X_WS = scene.SitePoseInWorld(site_id_);
  const Eigen::Matrix3d R_WS = X_WS.linear();
  const Eigen::Vector3d p_WS = X_WS.translation();
  std::normal_distribution<double> noise(0.0, options_.sigma_m);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const bool noisy = !options_.noise_free;
  RayHit hit;
  for (int i = 0; i < n; ++i) {
    double& r = scan.ranges_m[i];
    int& geom_id = out->hit_geom_ids[i];
    if (caster.Cast(p_WS, R_WS * dirs_S_[i], range_max_m, &hit) && hit.distance_m < range_max_m) {
      r = hit.distance_m;
      geom_id = hit.geom_id;
      if (noisy && options_.sigma_m > 0.0) r = std::max(0.0, r + noise(rng_));
      if (r >= range_max_m) {
        r = range_max_m;
        geom_id = -1;
      }
    } else {
      r = range_max_m;
      geom_id = -1;
    }
    if (noisy && options_.outlier_probability > 0.0 &&
        uniform(rng_) < options_.outlier_probability) {
      r = options_.range_min_m + uniform(rng_) * (range_max_m - options_.range_min_m);
      geom_id = -1;
    }
  }
}

}  // namespace plywood::sim
