#include "perception/geometric_map/range_fusion.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "msgs/angle_units.h"
#include "perception/geometric_map/option_checks.h"
#include "perception/lines/scan_points.h"

namespace plywood::perception {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

Eigen::Vector2d Direction(double angle_rad) { return {std::cos(angle_rad), std::sin(angle_rad)}; }

}  // namespace

const char* ToString(RangeSource source) {
  switch (source) {
    case RangeSource::kIrOnly:
      return "ir";
    case RangeSource::kSonarOnly:
      return "sonar";
    case RangeSource::kFused:
      break;
  }
  return "fused";
}

RangeSource ParseRangeSource(const std::string& text) {
  if (text == "fused") return RangeSource::kFused;
  if (text == "ir") return RangeSource::kIrOnly;
  if (text == "sonar") return RangeSource::kSonarOnly;
  throw std::invalid_argument("expected fused, ir or sonar, got '" + text + "'");
}

void FusionOptions::Validate() const {
  RequireOption(tau_m >= 0.0 && tau_m <= 1.0, "tau_m", "must be in [0, 1]", tau_m);
  RequireOption(sonar_half_angle_deg > 0.0 && sonar_half_angle_deg <= 45.0, "sonar_half_angle_deg",
                "must be in (0, 45]", sonar_half_angle_deg);
  RequireOption(fill_half_angle_deg > 0.0 && fill_half_angle_deg <= sonar_half_angle_deg,
                "fill_half_angle_deg", "must be in (0, sonar_half_angle_deg]", fill_half_angle_deg);
  RequireOption(sonar_max_range_m > 0.0 && sonar_max_range_m <= 20.0, "sonar_max_range_m",
                "must be in (0, 20]", sonar_max_range_m);
}

std::vector<RangePoint> FuseRanges(const msgs::LaserScan& ir, const msgs::RangeRing* sonar,
                                   const FusionOptions& options) {
  ValidateScanAngles(ir);
  const int n = static_cast<int>(ir.ranges_m.size());
  const Eigen::Vector2d origin(ir.X_RS.x_m, ir.X_RS.y_m);
  std::vector<Eigen::Vector2d> dir(n);
  std::vector<double> range(n, kInfinity);  // infinity: no range on this beam
  std::vector<char> from_sonar(n, 0);
  for (int i = 0; i < n; ++i) {
    dir[i] = Direction(ir.X_RS.theta_rad + ir.BeamAngleRad(i));
    if (options.source != RangeSource::kSonarOnly && ir.IsReturn(i)) range[i] = ir.ranges_m[i];
  }
  if (sonar != nullptr && options.source != RangeSource::kIrOnly) {
    const double cos_cone = std::cos(options.sonar_half_angle_deg * kDegToRad);
    const double cos_fill = std::cos(options.fill_half_angle_deg * kDegToRad);
    // Echoes are judged against the IR alone, so the order of the transducers does not matter.
    const std::vector<double> ir_range = range;
    const auto& readings = sonar->readings;
    const int count = static_cast<int>(readings.size());
    // Unexplained echoes: nearer than the IR's surface in their cone (or the IR saw nothing).
    std::vector<char> unexplained(count, 0);
    for (int j = 0; j < count; ++j) {
      const msgs::RangeReading& reading = readings[j];
      if (!reading.echo || reading.range_m > options.sonar_max_range_m) continue;
      const Eigen::Vector2d s(reading.X_RS.x_m, reading.X_RS.y_m);
      const Eigen::Vector2d axis = Direction(reading.X_RS.theta_rad);
      double d_ir = kInfinity;
      for (int i = 0; i < n; ++i) {
        if (!std::isfinite(ir_range[i])) continue;
        const Eigen::Vector2d v = origin + ir_range[i] * dir[i] - s;
        const double d = v.norm();
        if (d > 0.0 && v.dot(axis) >= cos_cone * d) d_ir = std::min(d_ir, d);
      }
      unexplained[j] = reading.range_m < d_ir - options.tau_m;
    }
    for (int j = 0; j < count; ++j) {
      if (!unexplained[j]) continue;
      const msgs::RangeReading& reading = readings[j];
      // A surface heard by neighbouring transducers is nearest along the one most square to it;
      // the others heard it off-axis, and squaring the surface to their axes would tilt it.
      const auto nearer = [&](int k) {
        k = (k + count) % count;
        return k != j && unexplained[k] && readings[k].range_m < reading.range_m;
      };
      if (count > 2 && (nearer(j - 1) || nearer(j + 1))) continue;
      const Eigen::Vector2d s(reading.X_RS.x_m, reading.X_RS.y_m);
      const Eigen::Vector2d axis = Direction(reading.X_RS.theta_rad);
      // An obstacle the IR missed: the surface square to the axis at the echo's range.
      for (int i = 0; i < n; ++i) {
        const double along = dir[i].dot(axis);
        if (along <= 1e-9) continue;
        const double t = (reading.range_m - (origin - s).dot(axis)) / along;
        if (t <= 0.0) continue;
        const Eigen::Vector2d v = origin + t * dir[i] - s;
        if (v.dot(axis) < cos_fill * v.norm()) continue;
        // Where the IR could not have seen anything (beyond its reach) its silence is no evidence.
        if (options.source == RangeSource::kFused && t >= ir.range_max_m - options.tau_m) continue;
        if (t < range[i] - options.tau_m ||
            (options.source == RangeSource::kSonarOnly && t < range[i])) {
          range[i] = t;
          from_sonar[i] = 1;
        }
      }
    }
  }
  std::vector<RangePoint> points;
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(range[i])) continue;
    points.push_back({origin + range[i] * dir[i], i, from_sonar[i] != 0});
  }
  return points;
}

}  // namespace plywood::perception
