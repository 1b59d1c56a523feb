#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sim/config/experiment_config.h"
#include "sim/world/scene.h"

namespace plywood::sim {

// Why the controller cannot do what the config asks of it in `scene` (the config's checked scene,
// at its spawn), or nullopt: a waypoint or a square's corner the robot can never reach (beyond the
// walls, inside a wall, a box or a table leg), a reach tolerance that takes in every waypoint from
// the spawn, a wheel speed limit above the wheel motors'. Reads only the config and the scene (no
// sensor, estimator or plug-in is made), so a sweep asks it of every cell before any runs.
struct ControllerTargetProblem {
  std::string field;    // e.g. "controller.waypoints[3]"
  std::string message;  // what is wrong and what to change
  // The key paths whose values the problem depends on ("world" among them when the world's walls
  // and geoms do): what a sweep axis, profile line or worlds entry may have set, e.g.
  // {"controller.side_m", "controller.direction", "robot.spawn", "world"}.
  std::vector<std::string> set_by;
};
std::optional<ControllerTargetProblem> FindControllerTargetProblem(const ExperimentConfig& config,
                                                                   const Scene& scene);

// FindControllerTargetProblem's problem as the ConfigError naming config.source_file and its field.
void RequireReachableControllerTargets(const ExperimentConfig& config, const Scene& scene);

}  // namespace plywood::sim
