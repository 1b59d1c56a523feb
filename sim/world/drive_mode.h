#pragma once

#include <string>

namespace plywood::sim {

// How Scene::Step moves the robot (`physics.drive` in an experiment).
//  - kContact (default): MuJoCo's mj_step, wheels on the floor through soft contacts.
//  - kPlanar: no mj_step; the base's planar pose is integrated from the wheel speeds, which follow
//    the velocity servos through the lag their gain and the robot's inertia give (PlanarDrive), and
//    the bumper ring's 2-D footprint stops the robot at static geoms (PlanarObstacles). For batch
//    runs where contact dynamics do not matter; it does not model slip, the caster or tire scrub.
enum class DriveMode { kContact, kPlanar };

std::string ToString(DriveMode mode);
// @throws std::invalid_argument "expected contact or planar, got 'TEXT'".
DriveMode ParseDriveMode(const std::string& text);

}  // namespace plywood::sim
