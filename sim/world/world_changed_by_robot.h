#pragma once

#include <mujoco/mujoco.h>

#include <optional>
#include <string>

namespace plywood::sim {

// The first part of the world that the scene (world and robot files compiled as one model)
// compiles differently from the world's file alone, as "geom 'wall_0': quat is ... with this
// robot, ... in the world's file alone (a <compiler> or <default> setting ...)"; nullopt when the
// world is as its file says. The mirror of RobotChangedByWorld: a robot file's <compiler> and
// <default> settings apply to every file of the model too, so a robot copied from elsewhere with
// <compiler angle="radian"/> (its own angles in radians, so it compiled alike alone) turned
// rotated_room.xml's walls by 20 rad instead of 20 deg, and walls.csv, the truth and the sensors
// all took the other room, exit 0. Compares the world's bodies and geoms (those on the world body
// and the bodies the world's file makes, which come first in the scene: ComposeSceneMjcf includes
// the world before the robot).
std::optional<std::string> WorldChangedByRobot(const mjModel* scene, const mjModel* world_alone);

}  // namespace plywood::sim
