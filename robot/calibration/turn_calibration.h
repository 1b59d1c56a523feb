#pragma once

#include <vector>

namespace plywood::robot {

// Seed 001's odometry calibration: the robot makes n turns on the spot of nominally 90 deg by its
// odometry, an external reference measures each true turn, and the mean error corrects both the
// turn commands and the odometry's track.
struct TurnObservation {
  double odometry_turn_rad = 0.0;  // what the odometry reported (signed, left positive)
  double true_turn_rad = 0.0;      // what the robot really turned
};

struct TurnCalibration {
  int turns = 0;
  // Mean of |true| - |odometry| in degrees: negative when the robot under-turns.
  double mean_error_deg = 0.0;
  double error_sigma_deg = 0.0;  // sample standard deviation of the same
  // E_b for the odometry: sum |odometry| / sum |true| (the track to believe is track_ratio times
  // the nominal one).
  double track_ratio = 1.0;
  // Factor on a turn command, for a robot that keeps its uncalibrated odometry: to turn a degrees
  // it must ask its odometry for a * command_scale (numerically track_ratio).
  double command_scale = 1.0;
};

// @throws std::invalid_argument when empty or when a turn is zero.
TurnCalibration CalibrateTurns(const std::vector<TurnObservation>& turns);

}  // namespace plywood::robot
