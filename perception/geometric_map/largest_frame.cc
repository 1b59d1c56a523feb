#include "perception/geometric_map/largest_frame.h"

#include <cmath>

#include "perception/geometric_map/option_checks.h"

namespace plywood::perception {

void LargestFrameOptions::Validate() const {
  RequireOption(d_max_m > 0.0 && d_max_m <= 50.0, "d_max_m", "must be in (0, 50]", d_max_m);
  RequireOption(min_peak_votes >= 1 && min_peak_votes <= 10000, "min_peak_votes",
                "must be in [1, 10000]", min_peak_votes);
}

std::array<Eigen::Vector2d, 2> LargestFrame::SideCorners(int side) const {
  const double xp = distance_m[0], yp = distance_m[1], xn = -distance_m[2], yn = -distance_m[3];
  // Corners of the rectangle in its own frame, counter-clockwise from (+x, -y).
  const std::array<Eigen::Vector2d, 4> c = {Eigen::Vector2d(xp, yn), Eigen::Vector2d(xp, yp),
                                            Eigen::Vector2d(xn, yp), Eigen::Vector2d(xn, yn)};
  const Eigen::Vector2d u(std::cos(alpha_rad), std::sin(alpha_rad)), v(-u.y(), u.x());
  const auto turn = [&](const Eigen::Vector2d& p) {
    return Eigen::Vector2d(p.x() * u + p.y() * v);
  };
  return {turn(c[side]), turn(c[(side + 1) % 4])};
}

LargestFrame FindLargestFrame(const DistanceHistograms& h, const LargestFrameOptions& options) {
  LargestFrame frame;
  frame.alpha_rad = h.alpha_rad;
  const std::array<const std::vector<DistancePeak>*, 4> sides = {&h.x_positive, &h.y_positive,
                                                                 &h.x_negative, &h.y_negative};
  for (int s = 0; s < 4; ++s) {
    double farthest = -1.0;
    for (const DistancePeak& peak : *sides[s]) {
      const double d = std::abs(peak.position_m);
      if (peak.votes >= options.min_peak_votes && d <= options.d_max_m) {
        farthest = std::max(farthest, d);
      }
    }
    frame.pseudo[s] = farthest < 0.0;
    frame.distance_m[s] = frame.pseudo[s] ? options.d_max_m : farthest;
  }
  return frame;
}

}  // namespace plywood::perception
