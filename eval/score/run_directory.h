#pragma once

#include <filesystem>
#include <string>

#include "sim/config/experiment_config.h"
#include "sim/world/ground_truth_walls.h"

namespace plywood::eval {

// The files of a finished run (docs/run_outputs.md) that the file scorers compare with.

// DIR/NAME, which must exist. @throws sim::ConfigError "DIR/NAME: missing (WHY)", or naming DIR
// when it is not a finished run (sim::RequireFinishedRun: killed, failed, truncated).
std::filesystem::path RunFile(const std::filesystem::path& run_dir, const std::string& name,
                              const std::string& why);

// DIR/config.yaml of a single run. @throws sim::ConfigError naming config.yaml when it is missing
// or bad, or when the run was a multi-run protocol (`command` is what cannot score it).
sim::ExperimentConfig LoadRunConfig(const std::filesystem::path& run_dir,
                                    const std::string& command);

// walls.csv back into segments (exact: it holds shortest round-trip numbers).
// @throws sim::ConfigError naming the file, line and field.
sim::GroundTruthWalls ReadWallsCsv(const std::filesystem::path& path);

}  // namespace plywood::eval
