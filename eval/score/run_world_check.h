#pragma once

#include <filesystem>
#include <string>

#include "sim/config/experiment_config.h"
#include "sim/world/ground_truth_walls.h"
#include "sim/world/scene.h"

namespace plywood::eval {

// A replay (and `plywood score grid`, whose ground truth is the world) compiles the world file
// named by the run's config.yaml as it is now. When that file changed since the run, the replay
// would show the logged path in another world, and the grid would be scored against it, without a
// word: the run's walls.csv (the box faces it saw, exact numbers) must match the faces the
// compiled world gives at the same height. Cylinders and other shapes are not in walls.csv, so a
// change to them alone is not caught. `consequence` ends the message ("a replay would show the
// run in another world").
// @throws sim::ConfigError naming config.yaml's `world` when they differ.
void RequireWorldAsTheRunSawIt(const sim::Scene& scene, const sim::ExperimentConfig& config,
                               const sim::GroundTruthWalls& run_walls,
                               const std::filesystem::path& config_yaml,
                               const std::string& consequence);

}  // namespace plywood::eval
