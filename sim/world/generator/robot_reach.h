#pragma once

#include <mujoco/mujoco.h>

#include "sim/config/robot_catalog.h"

namespace plywood::sim::worldgen {

// How far a robot reaches from its origin on the floor (the centre of rotation), seen from above:
// the radius of the smallest disc about the origin that covers every robot geom (collision and
// visual, bumpers included) with the robot standing at the origin. Exact for boxes, spheres,
// capsules, cylinders and meshes; ellipsoids count their bounding sphere.
// @pre `robot` is a robot file compiled alone (models/README.md: its base at the origin).
double RobotReachM(const mjModel* robot);

// The robot the testbed knows (sim/config/robot_catalog.h) with the largest RobotReachM, and that
// reach; computed once per process. The P3-DX: 0.345 m (its chassis shell's corners).
// @throws std::runtime_error when a robot file does not compile.
const RobotCatalogEntry& LargestRobot();
double LargestRobotReachM();

}  // namespace plywood::sim::worldgen
