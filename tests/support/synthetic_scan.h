#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "msgs/laser_scan.h"
#include "msgs/pose2d.h"

namespace plywood::test {

using Wall = std::pair<Eigen::Vector2d, Eigen::Vector2d>;

// A noise-free full-turn scan of `walls` (world frame) by a sensor at X_RS on a robot at X_WR:
// `beams` beams from -pi, range_max_m where nothing is nearer. The seed 003 IR head's geometry.
inline msgs::LaserScan SyntheticScan(const std::vector<Wall>& walls, const msgs::Pose2D& X_WR,
                                     int beams = 200, double range_max_m = 3.0,
                                     const msgs::Pose2D& X_RS = {}) {
  msgs::LaserScan scan;
  scan.angle_min_rad = -std::numbers::pi;
  scan.angle_increment_rad = 2.0 * std::numbers::pi / beams;
  scan.range_min_m = 0.05;
  scan.range_max_m = range_max_m;
  scan.X_RS = X_RS;
  const msgs::Pose2D X_WS = X_WR * X_RS;
  const Eigen::Vector2d o(X_WS.x_m, X_WS.y_m);
  for (int i = 0; i < beams; ++i) {
    const double angle = X_WS.theta_rad + scan.BeamAngleRad(i);
    const Eigen::Vector2d d(std::cos(angle), std::sin(angle));
    double best = range_max_m;
    for (const auto& [a, b] : walls) {
      const Eigen::Vector2d ab = b - a, ao = a - o;
      const double den = d.x() * ab.y() - d.y() * ab.x();
      if (std::abs(den) < 1e-12) continue;
      const double t = (ao.x() * ab.y() - ao.y() * ab.x()) / den;
      const double u = (ao.x() * d.y() - ao.y() * d.x()) / den;
      if (t > 0.0 && u >= 0.0 && u <= 1.0 && t < best) best = t;
    }
    scan.ranges_m.push_back(best);
  }
  return scan;
}

// The four sides of the rectangle [x0, x1] x [y0, y1] turned by `theta` about the origin.
inline std::vector<Wall> Rectangle(double x0, double y0, double x1, double y1, double theta = 0.0) {
  const double c = std::cos(theta), s = std::sin(theta);
  const auto turn = [&](double x, double y) {
    return Eigen::Vector2d(c * x - s * y, s * x + c * y);
  };
  const Eigen::Vector2d p0 = turn(x0, y0), p1 = turn(x1, y0), p2 = turn(x1, y1), p3 = turn(x0, y1);
  return {{p0, p1}, {p1, p2}, {p2, p3}, {p3, p0}};
}

}  // namespace plywood::test
