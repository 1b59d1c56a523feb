#include "sim/sensors/laser_sensor.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>

#include "msgs/shortest_number.h"
#include "sim/config/require_field.h"
#include "sim/sensors/noise_draws.h"

namespace plywood::sim {
namespace {

bool IsOneOf(double value, std::initializer_list<double> allowed) {
  for (const double a : allowed) {
    if (std::abs(value - a) < 1e-12) return true;
  }
  return false;
}

}  // namespace

void LaserOptions::Validate() const {
  RequireField(std::isfinite(fov_deg) && fov_deg > 0.0 && fov_deg <= 180.0, "fov_deg",
               "must be in (0, 180]", fov_deg);
  RequireField(IsOneOf(resolution_deg, {0.25, 0.5, 1.0}), "resolution_deg",
               "must be 0.25, 0.5 or 1 (the LMS 200's modes)", resolution_deg);
  const double steps = fov_deg / resolution_deg;
  RequireField(std::abs(steps - std::round(steps)) < 1e-9, "fov_deg",
               "must be a whole number of resolution_deg steps", fov_deg);
  RequireField(IsOneOf(range_max_m, {8.0, 16.0, 32.0, 80.0}), "range_max_m",
               "must be 8, 16, 32 or 80 (the LMS 200's range modes)", range_max_m);
  RequireField(std::isfinite(range_min_m) && range_min_m >= 0.0 && range_min_m < range_max_m,
               "range_min_m", "must be in [0, range_max_m)", range_min_m);
  RequireField(std::isfinite(range_noise_sigma_m) && range_noise_sigma_m >= 0.0,
               "range_noise_sigma_m", "must be >= 0", range_noise_sigma_m);
  // A sigma beyond the whole range leaves no geometry in the scan: most readings clip to 0 or the
  // maximum (the LMS 200's is 15 mm; the noisiest shipped sweep uses 0.01 m).
  RequireField(range_noise_sigma_m <= range_max_m, "range_noise_sigma_m",
               "must be at most range_max_m (" + msgs::ShortestNumber(range_max_m) +
                   " m): a larger noise leaves no geometry in the scan",
               range_noise_sigma_m);
  RequireField(dropout_probability >= 0.0 && dropout_probability <= 1.0, "dropout_probability",
               "must be in [0, 1]", dropout_probability);
  RequireField(std::isfinite(mixed_pixel_min_jump_m) && mixed_pixel_min_jump_m > 0.0,
               "mixed_pixel_min_jump_m", "must be > 0", mixed_pixel_min_jump_m);
  RequireField(mixed_pixel_probability >= 0.0 && mixed_pixel_probability <= 1.0,
               "mixed_pixel_probability", "must be in [0, 1]", mixed_pixel_probability);
  RequireField(std::isfinite(rate_hz) && rate_hz > 0.0 && rate_hz <= 75.0, "rate_hz",
               "must be in (0, 75] (the LMS 200's fastest scan)", rate_hz);
  // With mixed_pixels off the two are never read: `--set sensors.laser.mixed_pixel_probability=0.9`
  // ran without mixed pixels and without a word (s62). Their defaults still pass, as config.yaml
  // writes them for every laser.
  const LaserOptions defaults;
  for (const auto& [field, value, fallback] :
       {std::tuple{"mixed_pixel_min_jump_m", mixed_pixel_min_jump_m,
                   defaults.mixed_pixel_min_jump_m},
        std::tuple{"mixed_pixel_probability", mixed_pixel_probability,
                   defaults.mixed_pixel_probability}}) {
    if (!mixed_pixels && value != fallback) {
      throw std::invalid_argument(std::string(field) + ": " + msgs::ShortestNumber(value) +
                                  " is read only with mixed_pixels: true (it is false, so the "
                                  "value would change nothing): set mixed_pixels: true, or leave " +
                                  field + " at " + msgs::ShortestNumber(fallback));
    }
  }
}

double LaserOptions::RangeResolutionM() const { return range_max_m > 32.0 ? 0.01 : 0.001; }

int LaserOptions::BeamCount() const {
  return static_cast<int>(std::lround(fov_deg / resolution_deg)) + 1;
}

LaserSensor::LaserSensor(const Scene& scene, const std::string& site_name,
                         const LaserOptions& options, std::uint64_t seed)
    : options_((options.Validate(), options)),
      geometry_(scene, site_name, "the laser", -options_.fov_deg / 2.0, options_.resolution_deg,
                options_.BeamCount(), options_.range_max_m),
      true_ranges_m_(geometry_.beam_count()),
      rng_(seed) {}

ScanMeasurement LaserSensor::Measure(const Scene& scene, const RayCaster& caster) {
  ScanMeasurement out;
  Measure(scene, caster, &out);
  return out;
}

bool LaserSensor::IsDepthEdge(int near, int far, double angle_increment_rad) const {
  // A wall seen at a grazing angle also makes neighbouring ranges jump, but the far beam's hit
  // continues the near surface (the line through the near beam and its other neighbour): the
  // footprint covers one surface and returns its middle. Only a far hit off that line is an edge
  // the footprint can straddle. Without the other neighbour the jump counts as an edge.
  const int other = 2 * near - far;
  if (other < 0 || other >= geometry_.beam_count()) return true;
  const double r_other = true_ranges_m_[other];
  if (r_other >= options_.range_max_m) return true;
  const auto point = [&](int beam) {
    const double angle = beam * angle_increment_rad;  // relative angles suffice
    return Eigen::Vector2d(true_ranges_m_[beam] * std::cos(angle),
                           true_ranges_m_[beam] * std::sin(angle));
  };
  const Eigen::Vector2d p_near = point(near), p_other = point(other), p_far = point(far);
  const Eigen::Vector2d along = p_near - p_other;
  const double length = along.norm();
  if (length < 1e-9) return true;
  const Eigen::Vector2d d = p_far - p_near;
  const double off_line_m = std::abs(along.x() * d.y() - along.y() * d.x()) / length;
  return off_line_m > 0.5 * options_.mixed_pixel_min_jump_m;
}

void LaserSensor::Measure(const Scene& scene, const RayCaster& caster, ScanMeasurement* out) {
  geometry_.Cast(scene, caster, options_.range_min_m, options_.range_max_m, out);
  if (options_.noise_free) return;

  const int n = geometry_.beam_count();
  const double range_max_m = options_.range_max_m;
  msgs::LaserScan& scan = out->scan;
  if (options_.mixed_pixels) {
    std::copy(scan.ranges_m.begin(), scan.ranges_m.end(), true_ranges_m_.begin());
    for (int i = 0; i + 1 < n; ++i) {
      const double a = true_ranges_m_[i], b = true_ranges_m_[i + 1];
      if (a >= range_max_m || b >= range_max_m) continue;
      if (std::abs(a - b) <= options_.mixed_pixel_min_jump_m) continue;
      const int far = a > b ? i : i + 1;
      const int near = a > b ? i + 1 : i;
      if (!IsDepthEdge(near, far, scan.angle_increment_rad)) continue;
      if (UnitUniform(rng_) >= options_.mixed_pixel_probability) continue;
      const double near_m = std::min(a, b);
      scan.ranges_m[far] = near_m + UnitUniform(rng_) * std::abs(a - b);
      out->hit_geom_ids[far] = -1;  // a phantom point on no surface
    }
  }

  NormalDraws noise;  // a new pair state per scan, as before
  const double unit_m = options_.RangeResolutionM();
  // Every returned beam draws once for its dropout. With no dropout (the default) the draw cannot
  // succeed (a uniform is >= 0), so the engine only skips it: discard(1) leaves the engine as one
  // draw does (the standard's definition), without tempering and scaling a number nobody reads.
  const bool dropouts = options_.dropout_probability > 0.0;
  const auto dropped = [&] {
    if (dropouts) return UnitUniform(rng_) < options_.dropout_probability;
    rng_.discard(1);
    return false;
  };
  for (int i = 0; i < n; ++i) {
    double& r = scan.ranges_m[i];
    if (r >= range_max_m) continue;
    if (options_.range_noise_sigma_m > 0.0) r += noise(rng_, 0.0, options_.range_noise_sigma_m);
    r = std::max(0.0, std::round(r / unit_m) * unit_m);
    if (r >= range_max_m || dropped()) {
      r = range_max_m;
      out->hit_geom_ids[i] = -1;
    }
  }
}

}  // namespace plywood::sim
