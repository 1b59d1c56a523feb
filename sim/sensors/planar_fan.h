#pragma once

#include <Eigen/Core>
#include <vector>

namespace plywood::sim {

// Beam directions of the planar range sensors. Angles are measured counter-clockwise from the
// sensor site's x axis, in the site's x-y plane, so the beams tilt with the robot.

// n angles (rad): first_deg + i * step_deg for i in [0, n), a scanner's beams.
std::vector<double> EvenAnglesRad(double first_deg, double step_deg, int n);

// n angles (rad) spread evenly over [-half_angle_deg, +half_angle_deg], both ends included; a
// single ray lies on the axis. The rays of one sonar or IR beam.
std::vector<double> SymmetricFanAnglesRad(double half_angle_deg, int n);

// Unit vectors (cos a, sin a, 0) in the site frame.
std::vector<Eigen::Vector3d> PlanarDirections(const std::vector<double>& angles_rad);

}  // namespace plywood::sim
