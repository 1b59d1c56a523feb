#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "msgs/laser_scan.h"
#include "msgs/pose2d.h"

namespace plywood::perception {

// The usable returns of one scan in beam order, in both views: polar (range, bearing) and
// Cartesian (x, y) in the frame of the first sensor (S). Line extractors work on this.
struct ScanPoints {
  std::vector<double> range_m;
  std::vector<double> bearing_rad;
  std::vector<Eigen::Vector2d> points;  // p_S
  std::vector<int> beam_index;          // index of the beam in the concatenated source scans
  double angle_increment_rad = 0.0;     // bearing step between neighbouring beams
  // True when the scan covers a full turn, so the last point neighbours the first (seed 000's two
  // back-to-back LMS 200).
  bool closed = false;
  // The returns a range cut removed (ScanFilter::range_cut_m: valid, but farther than the cut), in
  // beam order. Never a line's point: what lies just past the cut tells a wall that continues
  // beyond it from an object whose near side alone is inside it (round_past_range_cut.h).
  std::vector<double> beyond_cut_range_m;
  std::vector<double> beyond_cut_bearing_rad;
  std::vector<int> beyond_cut_beam_index;

  std::size_t size() const { return points.size(); }
  bool empty() const { return points.empty(); }
  // Whether the polar view and beam indices go with the points (filled by Add), not bare points.
  bool HasScanOrder() const {
    return range_m.size() == points.size() && beam_index.size() == points.size();
  }
  // A range that is NaN, infinite or <= 0, or a bearing that is not finite, is no return: skipped.
  void Add(double range_m, double bearing_rad, int beam);
  // Beams without a usable return between point i and the next point j in scan order (past the
  // seam of a closed scan too): no return, a dropout, or a return filtered out (range cut).
  // Inline: the breakpoint test asks it for every pair of neighbouring points.
  int MissingBeams(int i, int j) const {
    int steps = beam_index[j] - beam_index[i];
    if (steps <= 0 && closed && angle_increment_rad != 0.0) {
      // Past the seam: the beams of a full turn.
      steps +=
          static_cast<int>(std::lround(2.0 * std::numbers::pi / std::abs(angle_increment_rad)));
    }
    return std::max(0, steps - 1);
  }
};

// Which returns become points: range_min_m < r < range_max_m (strict on both sides, so ranges
// reported at the sensor's maximum never pass) and r <= range_cut_m (seed 000's "max range used").
struct ScanFilter {
  double range_min_m = 0.05;
  double range_max_m = 1e9;  // typically the sensor's maximum, minus a margin for real logs
  double range_cut_m = 1e9;

  // The valid-ray rule of plywood replay: 0.05 m < r < M - 0.2 m.
  static ScanFilter ForLog(double log_range_max_m) { return {0.05, log_range_max_m - 0.2, 1e9}; }
  bool Passes(double r_m) const {
    return r_m > range_min_m && r_m < range_max_m && r_m <= range_cut_m;
  }
  // A valid return that only the range cut removes.
  bool BeyondCut(double r_m) const {
    return r_m > range_min_m && r_m < range_max_m && r_m > range_cut_m;
  }
};

// Refuses, once per scan, angles that cannot place its beams: a non-finite angle_min_rad, or an
// angle_increment_rad that is 0 or not finite with more than one beam (every beam on one ray).
// @throws std::invalid_argument "<field>: must be ..., got <value>".
void ValidateScanAngles(const msgs::LaserScan& scan);

// The scan's returns that pass `filter` (and scan.IsReturn), in the sensor frame; those only the
// range cut removed go to the beyond_cut_* fields. NaN, inf, < range_min_m and >= range_max_m
// ranges are no return; each scan's angles go through ValidateScanAngles.
ScanPoints MakeScanPoints(const msgs::LaserScan& scan, const ScanFilter& filter);

// Several scans taken from one spot, combined in the frame of the first sensor: scans[k] is
// rotated by X_SSk.theta_rad (the sensors must share an origin, as two back-to-back LMS 200 do).
// Beam indices run over the concatenation. `closed` is set when the bearings cover a full turn.
ScanPoints MakeCombinedScanPoints(const std::vector<msgs::LaserScan>& scans,
                                  const std::vector<double>& heading_offsets_rad,
                                  const ScanFilter& filter);

}  // namespace plywood::perception
