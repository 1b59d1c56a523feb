#pragma once

#include <memory>

#include "sim/config/experiment_config.h"
#include "sim/world/scene.h"

namespace plywood::sim {

// The config's world compiled with its robot at its spawn (the as-built wheels deviated by
// robot.deviation), refused (ConfigError, one line naming the world or robot.spawn) when it
// cannot give meaningful results: no floor, geoms the robot or the sensors pass through, changed
// physics, a spawn outside every room or inside a wall. What ExperimentRunner builds first; a
// sweep calls it once per hand-given world before any cell runs.
std::unique_ptr<Scene> MakeCheckedScene(const ExperimentConfig& config);

}  // namespace plywood::sim
