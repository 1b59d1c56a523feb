#include "perception/geometric_map/scan_histograms.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "msgs/angle_units.h"
#include "perception/geometric_map/option_checks.h"

namespace plywood::perception {
namespace {

// Direction of a line modulo pi, in [0, pi).
double LineDirection(double angle_rad) {
  double a = std::fmod(angle_rad, kPi);
  if (a < 0.0) a += kPi;
  if (a >= kPi) a -= kPi;
  return a;
}

}  // namespace

void HistogramOptions::Validate() const {
  RequireOption(gamma_beams >= 1 && gamma_beams <= 100, "gamma_beams", "must be in [1, 100]",
                gamma_beams);
  RequireOption(max_virtual_line_m > 0.0 && max_virtual_line_m <= 10.0, "max_virtual_line_m",
                "must be in (0, 10]", max_virtual_line_m);
  RequireOption(angle_bin_deg >= 0.05 && angle_bin_deg <= 30.0, "angle_bin_deg",
                "must be in [0.05, 30]", angle_bin_deg);
  RequireOption(distance_bin_m >= 0.005 && distance_bin_m <= 1.0, "distance_bin_m",
                "must be in [0.005, 1]", distance_bin_m);
  RequireOption(max_wall_tilt_deg > 0.0 && max_wall_tilt_deg < 45.0, "max_wall_tilt_deg",
                "must be in (0, 45)", max_wall_tilt_deg);
  RequireOption(maxima_per_side >= 1 && maxima_per_side <= 20, "maxima_per_side",
                "must be in [1, 20]", maxima_per_side);
}

double AngleHistogram::MainDirectionRad() const {
  const int bins = static_cast<int>(votes.size());
  if (bins == 0 || directions_rad.empty()) return 0.0;
  int mode = 0;
  double best = -1.0;
  for (int b = 0; b < bins; ++b) {
    const double v = votes[(b + bins - 1) % bins] + votes[b] + votes[(b + 1) % bins];
    if (v > best) best = v, mode = b;
  }
  double c2 = 0.0, s2 = 0.0;
  for (double a : directions_rad) {
    const int b = std::min(bins - 1, static_cast<int>(a / kPi * bins));
    const int d = std::abs(b - mode);
    if (std::min(d, bins - d) > 1) continue;
    c2 += std::cos(2.0 * a);
    s2 += std::sin(2.0 * a);
  }
  return LineDirection(0.5 * std::atan2(s2, c2));
}

std::vector<VirtualLine> MakeVirtualLines(std::span<const RangePoint> points,
                                          const HistogramOptions& options) {
  std::vector<VirtualLine> lines;
  // Pairs exactly gamma_beams beams apart; points are in beam order, so the partner is near.
  for (std::size_t k = 0; k < points.size(); ++k) {
    for (std::size_t j = k + 1; j < points.size(); ++j) {
      const int step = points[j].beam - points[k].beam;
      if (step < options.gamma_beams) continue;
      if (step > options.gamma_beams) break;
      const Eigen::Vector2d v = points[j].p_R - points[k].p_R;
      if (v.norm() > options.max_virtual_line_m || v.norm() < 1e-12) break;
      lines.push_back({static_cast<int>(k), LineDirection(std::atan2(v.y(), v.x()))});
      break;
    }
  }
  return lines;
}

AngleHistogram MakeAngleHistogram(std::span<const RangePoint> points,
                                  const HistogramOptions& options, double offset_rad) {
  AngleHistogram h;
  h.bin_deg = options.angle_bin_deg;
  const int bins = std::max(1, static_cast<int>(std::lround(180.0 / options.angle_bin_deg)));
  h.votes.assign(bins, 0.0);
  for (const VirtualLine& line : MakeVirtualLines(points, options)) {
    const double a = LineDirection(line.direction_rad + offset_rad);
    h.directions_rad.push_back(a);
    h.votes[std::min(bins - 1, static_cast<int>(a / kPi * bins))] += 1.0;
  }
  return h;
}

std::vector<DistancePeak> StrongestMaxima(std::span<const double> coordinates, double bin_m,
                                          bool positive, int count) {
  std::map<long, std::vector<double>> bins;  // ordered, so ties resolve the same way every time
  for (double c : coordinates) {
    if ((c > 0.0) != positive) continue;
    bins[static_cast<long>(std::floor(c / bin_m))].push_back(c);
  }
  const auto votes = [&](long b) {
    const auto it = bins.find(b);
    return it == bins.end() ? 0.0 : static_cast<double>(it->second.size());
  };
  std::vector<DistancePeak> peaks;
  for (const auto& [b, members] : bins) {
    const double v = votes(b);
    if (v < votes(b - 1) || v <= votes(b + 1)) continue;  // plateaus count once, at their far end
    std::vector<double> near;
    for (long k = b - 1; k <= b + 1; ++k) {
      const auto it = bins.find(k);
      if (it != bins.end()) near.insert(near.end(), it->second.begin(), it->second.end());
    }
    std::sort(near.begin(), near.end());
    const std::size_t m = near.size() / 2;
    const double median = near.size() % 2 ? near[m] : 0.5 * (near[m - 1] + near[m]);
    peaks.push_back({median, static_cast<double>(near.size())});
  }
  std::stable_sort(peaks.begin(), peaks.end(), [](const DistancePeak& a, const DistancePeak& b) {
    if (a.votes != b.votes) return a.votes > b.votes;
    return std::abs(a.position_m) < std::abs(b.position_m);
  });
  if (static_cast<int>(peaks.size()) > count) peaks.resize(count);
  return peaks;
}

DistanceHistograms MakeDistanceHistograms(std::span<const RangePoint> points, double alpha_rad,
                                          const HistogramOptions& options) {
  DistanceHistograms h;
  h.alpha_rad = alpha_rad;
  const Eigen::Vector2d u(std::cos(alpha_rad), std::sin(alpha_rad)), v(-u.y(), u.x());
  // A point votes for X when its virtual line runs along Y (square to X), and vice versa.
  const double max_tilt = options.max_wall_tilt_deg * kPi / 180.0;
  std::vector<double> xs, ys;
  for (const VirtualLine& line : MakeVirtualLines(points, options)) {
    const double off_x = std::abs(std::remainder(line.direction_rad - alpha_rad, kPi));
    const Eigen::Vector2d& p = points[line.first].p_R;
    if (off_x <= max_tilt) ys.push_back(p.dot(v));
    if (std::abs(off_x - kPi / 2.0) <= max_tilt) xs.push_back(p.dot(u));
  }
  const double bin = options.distance_bin_m;
  const int count = options.maxima_per_side;
  h.x_negative = StrongestMaxima(xs, bin, false, count);
  h.x_positive = StrongestMaxima(xs, bin, true, count);
  h.y_negative = StrongestMaxima(ys, bin, false, count);
  h.y_positive = StrongestMaxima(ys, bin, true, count);
  return h;
}

}  // namespace plywood::perception
