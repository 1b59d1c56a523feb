#pragma once

#include <mujoco/mujoco.h>

#include <optional>
#include <string>

namespace plywood::sim {

// The first part of the robot that the scene (world and robot files compiled as one model)
// compiles differently from the robot's file alone, as "site 'sonar_0': quat is ... in this
// world, ... in the robot's file alone"; nullopt when the robot is as its file says. A world's
// <compiler> and <default> settings apply to every file of the model: a world written with
// angle="radian" (as many MJCF files from elsewhere are) turned the robot's euler="0 0 90"
// sonars and its wheels by 90 rad, and a <default> geom friction reached the chassis, without a
// word. Compares the robot's bodies, geoms, sites, joints and actuators (the robot's `base`
// subtree in both models), and counts the actuators, equality constraints, tendons and contact
// pairs or exclusions between robot and world that the world may add (an <exclude> of a wheel and
// the world dropped the wheel through the floor).
std::optional<std::string> RobotChangedByWorld(const mjModel* scene, const mjModel* robot_alone);

}  // namespace plywood::sim
