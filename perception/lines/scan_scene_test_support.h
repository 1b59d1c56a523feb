#pragma once

// Hand-made scans for the line-extraction tests: exact ray casts of polygons and discs from the
// origin, with optional Gaussian range noise. Test-only (header-only, no library code uses it).

#include <Eigen/Core>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "msgs/laser_scan.h"
#include "perception/lines/ray_polygon.h"
#include "perception/lines/scan_points.h"

namespace plywood::perception::testing {

struct Disc {
  Eigen::Vector2d centre;
  double radius_m;
};

// A closed 720-beam scan (0.5 deg, two back-to-back LMS 200) from the origin of polygons (each a
// closed chain of corners) and discs, with Gaussian range noise (seeded). Beams that hit nothing
// within range_max_m give no return; returns past range_cut_m are left out (ScanFilter).
inline ScanPoints ScanScene(const std::vector<std::vector<Eigen::Vector2d>>& polygons,
                            const std::vector<Disc>& discs, double noise_m = 0.0,
                            double range_max_m = 20.0, unsigned seed = 11,
                            double range_cut_m = 1e9) {
  constexpr double kPi = std::numbers::pi;
  msgs::LaserScan scan;
  scan.angle_min_rad = -kPi;
  scan.angle_increment_rad = kPi / 360.0;
  scan.range_max_m = range_max_m;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_m);
  for (int i = 0; i < 720; ++i) {
    const double a = scan.BeamAngleRad(i);
    const Eigen::Vector2d d(std::cos(a), std::sin(a));
    double best = range_max_m;
    for (const auto& corners : polygons) best = RayToPolygonM(d, corners, best);
    for (const Disc& disc : discs) {
      const double along = disc.centre.dot(d);
      const double off_sq = disc.centre.squaredNorm() - along * along;
      const double r_sq = disc.radius_m * disc.radius_m;
      if (off_sq <= r_sq && along > 0) best = std::min(best, along - std::sqrt(r_sq - off_sq));
    }
    const double n = noise_m > 0 ? noise(rng) : 0.0;
    scan.ranges_m.push_back(best < range_max_m ? best + n : range_max_m);
  }
  ScanPoints points = MakeScanPoints(scan, ScanFilter{.range_cut_m = range_cut_m});
  points.closed = true;
  return points;
}

// A thin rectangle (a wall piece of 2 cm thickness) from a to b, as a polygon for ScanScene.
inline std::vector<Eigen::Vector2d> Panel(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                          double thickness_m = 0.02) {
  const Eigen::Vector2d u = (b - a).normalized();
  const Eigen::Vector2d n = thickness_m * Eigen::Vector2d(-u.y(), u.x());
  return {a, b, b + n, a + n};
}

}  // namespace plywood::perception::testing
