#include "perception/lines/scan_points.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "msgs/shortest_number.h"

namespace plywood::perception {

void ScanPoints::Add(double r, double bearing, int beam) {
  // No return, as a real driver reports it (NaN, inf, 0, a negative range) or a beam without a
  // direction: never a point, so never part of a line; the beam counts as missing.
  if (!(r > 0.0 && r < std::numeric_limits<double>::infinity()) || !std::isfinite(bearing)) return;
  range_m.push_back(r);
  bearing_rad.push_back(bearing);
  points.emplace_back(r * std::cos(bearing), r * std::sin(bearing));
  beam_index.push_back(beam);
}

void ValidateScanAngles(const msgs::LaserScan& scan) {
  if (!std::isfinite(scan.angle_min_rad)) {
    throw std::invalid_argument("angle_min_rad: must be finite, got " +
                                msgs::ShortestNumber(scan.angle_min_rad));
  }
  if (scan.ranges_m.size() > 1 &&
      !(std::isfinite(scan.angle_increment_rad) && scan.angle_increment_rad != 0.0)) {
    throw std::invalid_argument("angle_increment_rad: must be finite and non-zero, got " +
                                msgs::ShortestNumber(scan.angle_increment_rad));
  }
}

ScanPoints MakeScanPoints(const msgs::LaserScan& scan, const ScanFilter& filter) {
  return MakeCombinedScanPoints({scan}, {0.0}, filter);
}

ScanPoints MakeCombinedScanPoints(const std::vector<msgs::LaserScan>& scans,
                                  const std::vector<double>& heading_offsets_rad,
                                  const ScanFilter& filter) {
  if (scans.size() != heading_offsets_rad.size()) {
    throw std::invalid_argument("heading_offsets_rad: need one offset per scan");
  }
  ScanPoints out;
  int beam = 0;
  double covered_rad = 0.0;
  for (std::size_t k = 0; k < scans.size(); ++k) {
    const msgs::LaserScan& scan = scans[k];
    ValidateScanAngles(scan);
    if (k == 0) out.angle_increment_rad = scan.angle_increment_rad;
    covered_rad += std::abs(scan.angle_increment_rad) * static_cast<double>(scan.ranges_m.size());
    for (std::size_t i = 0; i < scan.ranges_m.size(); ++i, ++beam) {
      const double r = scan.ranges_m[i];
      if (!std::isfinite(r) || !scan.IsReturn(i)) continue;
      if (filter.Passes(r)) {
        out.Add(r, scan.BeamAngleRad(i) + heading_offsets_rad[k], beam);
      } else if (filter.BeyondCut(r)) {
        out.beyond_cut_range_m.push_back(r);
        out.beyond_cut_bearing_rad.push_back(scan.BeamAngleRad(i) + heading_offsets_rad[k]);
        out.beyond_cut_beam_index.push_back(beam);
      }
    }
  }
  out.closed = scans.size() > 1 && covered_rad >= 2.0 * std::numbers::pi - 1e-9;
  return out;
}

}  // namespace plywood::perception
