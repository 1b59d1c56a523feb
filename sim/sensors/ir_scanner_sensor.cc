#include "sim/sensors/ir_scanner_sensor.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "sim/config/require_field.h"
#include "sim/sensors/noise_draws.h"

namespace plywood::sim {
namespace {

constexpr double kMinIrResolutionDeg = 0.01;

}  // namespace

void IrScannerOptions::Validate() const {
  RequireField(std::isfinite(fov_deg) && fov_deg > 0.0 && fov_deg <= 360.0, "fov_deg",
               "must be in (0, 360]", fov_deg);
  RequireField(std::isfinite(resolution_deg) && resolution_deg > 0.0 && resolution_deg <= fov_deg,
               "resolution_deg", "must be in (0, fov_deg]", resolution_deg);
  // Every beam is cast each scan: 1e-6 deg (3.6e8 beams) had not finished a 1 s run after 60 s,
  // 1e-9 ended on "vector::reserve", and 1e-300 overflowed the beam count into a scanner of 0
  // beams that ran, exit 0 (s50). 0.01 deg is 36000 beams a turn, 180 times the shipped 1.8 deg.
  RequireField(resolution_deg >= kMinIrResolutionDeg, "resolution_deg",
               "must be at least " + msgs::ShortestNumber(kMinIrResolutionDeg) +
                   " deg (36000 beams a turn: finer scans never finish or exhaust memory)",
               resolution_deg);
  const double steps = fov_deg / resolution_deg;
  RequireField(std::abs(steps - std::round(steps)) < 1e-9, "fov_deg",
               "must be a whole number of resolution_deg steps", fov_deg);
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
  RequireField(outlier_probability >= 0.0 && outlier_probability <= 1.0, "outlier_probability",
               "must be in [0, 1]", outlier_probability);
  RequireField(std::isfinite(rate_hz) && rate_hz > 0.0, "rate_hz", "must be > 0", rate_hz);
}

int IrScannerOptions::BeamCount() const {
  const int steps = static_cast<int>(std::lround(fov_deg / resolution_deg));
  return std::abs(fov_deg - 360.0) < 1e-9 ? steps : steps + 1;
}

std::vector<char> IrInvisibleGeoms(const mjModel* model) {
  std::vector<char> invisible(model->ngeom, 0);
  const std::string prefix = kIrInvisiblePrefix;
  for (int g = 0; g < model->ngeom; ++g) {
    const int material = model->geom_matid[g];
    if (material < 0) continue;
    const char* name = mj_id2name(model, mjOBJ_MATERIAL, material);
    invisible[g] = name != nullptr && std::string(name).rfind(prefix, 0) == 0;
  }
  return invisible;
}

IrScannerSensor::IrScannerSensor(const Scene& scene, const std::string& site_name,
                                 const IrScannerOptions& options, std::uint64_t seed)
    : options_((options.Validate(), options)),
      geometry_(scene, site_name, "the IR scanner", -options_.fov_deg / 2.0,
                options_.resolution_deg, options_.BeamCount(), options_.range_max_m),
      invisible_(IrInvisibleGeoms(scene.model())),
      rng_(seed) {}

ScanMeasurement IrScannerSensor::Measure(const Scene& scene, const RayCaster& caster) {
  ScanMeasurement out;
  Measure(scene, caster, &out);
  return out;
}

void IrScannerSensor::Measure(const Scene& scene, const RayCaster& caster, ScanMeasurement* out) {
  geometry_.Cast(scene, caster, options_.range_min_m, options_.range_max_m, out, &invisible_);
  if (options_.noise_free) return;

  const int n = geometry_.beam_count();
  const double range_max_m = options_.range_max_m;
  NormalDraws noise;
  for (int i = 0; i < n; ++i) {
    double& r = out->scan.ranges_m[i];
    int& geom_id = out->hit_geom_ids[i];
    if (r < range_max_m && options_.sigma_m > 0.0) {  // a return (misses report range_max_m)
      r = std::max(0.0, r + noise(rng_, 0.0, options_.sigma_m));
      if (r >= range_max_m) {
        r = range_max_m;
        geom_id = -1;
      }
    }
    if (options_.outlier_probability > 0.0 && UnitUniform(rng_) < options_.outlier_probability) {
      r = options_.range_min_m + UnitUniform(rng_) * (range_max_m - options_.range_min_m);
      geom_id = -1;
    }
  }
}

}  // namespace plywood::sim
