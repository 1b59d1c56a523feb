#pragma once

#include <array>

#include "perception/geometric_map/scan_histograms.h"

namespace plywood::perception {

// Seed 003's "largest frame": the rectangle around the robot, aligned with the scan's main
// direction, bounded on each side by the farthest structure the distance histograms show there
// (a maximum with at least min_peak_votes points, no farther than d_max_m), or, when there is
// none, by d_max_m with the attribute 'pseudo' (the scan saw nothing that far on that side).
// d_max_m defaults to the IR scanner's reach; 8 points are about 25 cm of wall at 1.8 m.
struct LargestFrameOptions {
  double d_max_m = 3.0;
  int min_peak_votes = 8;

  // @throws std::invalid_argument starting with the field's name.
  void Validate() const;
};

// Sides in the order +x, +y, -x, -y of the frame turned by alpha_rad (counter-clockwise).
struct LargestFrame {
  double alpha_rad = 0.0;
  std::array<double, 4> distance_m{};  // from the robot to each side, >= 0
  std::array<bool, 4> pseudo{};

  // The side's two corners in the scan's frame, counter-clockwise around the frame.
  std::array<Eigen::Vector2d, 2> SideCorners(int side) const;
};

LargestFrame FindLargestFrame(const DistanceHistograms& histograms,
                              const LargestFrameOptions& options);

}  // namespace plywood::perception
