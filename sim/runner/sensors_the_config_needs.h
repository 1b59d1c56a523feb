#pragma once

#include "sim/config/experiment_config.h"

namespace plywood::sim {

// The runner's checks that what the config asks for has the sensors it reads, from the config
// alone (no scene): so a sweep asks them of every cell before any runs.

// A controller, map or line scorer that reads a sensor the experiment turned off (a wall follower
// by laser without the laser, seed 003's map without the IR scanner or an estimator, `lines:`
// without the laser). @throws ConfigError naming the field.
void RequireControllerSensors(const ExperimentConfig& config);

// Odometry estimators without the encoders, a gyro-using estimator without the gyro.
// @throws ConfigError naming the field.
void RequireOdometrySensors(const ExperimentConfig& config);

}  // namespace plywood::sim
