#include "sim/sensors/planar_fan.h"

#include <cmath>
#include <numbers>

#include "msgs/angle_units.h"

namespace plywood::sim {

std::vector<double> EvenAnglesRad(double first_deg, double step_deg, int n) {
  std::vector<double> angles_rad;
  angles_rad.reserve(n);
  for (int i = 0; i < n; ++i) angles_rad.push_back((first_deg + i * step_deg) * kDegToRad);
  return angles_rad;
}

std::vector<double> SymmetricFanAnglesRad(double half_angle_deg, int n) {
  std::vector<double> angles_rad;
  angles_rad.reserve(n);
  for (int j = 0; j < n; ++j) {
    angles_rad.push_back(
        n == 1 ? 0.0 : half_angle_deg * kDegToRad * (-1.0 + 2.0 * j / static_cast<double>(n - 1)));
  }
  return angles_rad;
}

std::vector<Eigen::Vector3d> PlanarDirections(const std::vector<double>& angles_rad) {
  std::vector<Eigen::Vector3d> dirs;
  dirs.reserve(angles_rad.size());
  for (const double a : angles_rad) dirs.emplace_back(std::cos(a), std::sin(a), 0.0);
  return dirs;
}

}  // namespace plywood::sim
