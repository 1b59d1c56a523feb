#pragma once

#include <memory>
#include <string>

#include "eval/sonar_map/sonar_ground_truth.h"
#include "sim/runner/experiment_runner.h"

namespace plywood::eval {

// When the run was driven by seed 001's SonarExplorer: scores its map against the world's ground
// truth and adds occupancy.error (e = A_e / A_tot of the partition map), occupancy.grid_error (of
// the grid thresholded at P > 0.5, unseen cells free), occupancy.partitions, occupancy.graph_nodes,
// occupancy.graph_edges and occupancy.rings. A_tot is the reachable free area inside the room's
// bounding box; A_e the area inside that box whose free/not-free label differs. The map lives in
// the odometry frame, which starts at the spawn pose, so it is compared in place. Returns false
// (and does nothing) for any other controller. `truth`: the one RequireASonarMapTruth returned
// before the run (the same world and spawn), else it is made here.
bool AddSonarMapMetrics(sim::ExperimentRunner& runner, const OccupancyTruth* truth = nullptr);

// Before a run driven by seed 001's SonarExplorer: the ground truth its map will be scored against
// can be made (the spawn in free space, the world within the raster's limit) and the free space
// round the spawn is closed by the world's walls. In a room with a wall left out the robot drove
// out through the gap and its perimeter ended on its time limit 5 m outside, yet the run ended
// `map_complete` with occupancy.error 0.0038 against a truth cut at the walls' bounding box (s61).
// Returns that truth, for AddSonarMapMetrics after the run; null for other controllers.
// @throws sim::ConfigError naming the experiment file and `world` (or `robot.spawn`).
std::unique_ptr<OccupancyTruth> RequireASonarMapTruth(const sim::ExperimentRunner& runner);

// Writes DIR/cognitive_map.json (eval/sonar_map/cognitive_map_json.h): the map the explorer
// built, in its odometry frame. No-op for other controllers.
void WriteSonarMap(const sim::ExperimentRunner& runner, const std::string& out_dir);

// Writes DIR/occupancy_grid.png and DIR/occupancy_partitions.png (partitions, graph and the true
// geometry in red). No-op for other controllers.
void WriteSonarMapPictures(const sim::ExperimentRunner& runner, const std::string& out_dir);

}  // namespace plywood::eval
