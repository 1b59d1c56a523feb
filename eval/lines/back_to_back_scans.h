#pragma once

#include <Eigen/Core>
#include <vector>

#include "eval/lines/line_scan_scorer.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"

namespace plywood::eval {

// Seed 000's rig: two SICK LMS 200 back to back at one spot, together 360 deg (2 x 361 = 722
// points at 0.5 deg). The P3-DX carries one forward-facing laser, so the rig is made of two idle
// runs of `config` (its world, robot and sensors.laser options): the robot is spawned so that its
// laser site lies exactly on `p_W`, once facing theta_rad and once theta_rad + pi, and stands
// still for `scans` scans each (independent noise per scan; the second run's sensors are seeded
// from config.seed + 1). Both sensors then share an origin, as the paper's pair nearly does.
struct BackToBackScans {
  std::vector<sim::LaserRecord> front;  // facing theta
  std::vector<sim::LaserRecord> back;   // facing theta + pi
  sim::GroundTruthWalls walls;
};

// @throws sim::ConfigError / std::invalid_argument when the config has no laser or the robot cannot
// stand there.
BackToBackScans TakeBackToBackScans(const sim::ExperimentConfig& config, const Eigen::Vector2d& p_W,
                                    double theta_rad, int scans);

// The scan pairs as TruthScans in the front sensor's frame (closed 360-deg scans).
std::vector<TruthScan> MakeTruthScans(const BackToBackScans& rig, double range_cut_m);

}  // namespace plywood::eval
