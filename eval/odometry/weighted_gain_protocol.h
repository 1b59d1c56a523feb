#pragma once

#include "eval/protocol.h"

namespace plywood::eval {

// `protocol: weighted_gain_search` (seed 004 eq. 5): drives the experiment once (a calibration
// run, not one of the runs that are evaluated afterwards), replays its encoder and gyro messages
// through WeightedFusedOdometry for every gain pair of the grid
//   weighted_gain_search: {min_gain: 0.9, max_gain: 1.1, step: 0.005}
// and reports the pair with the lowest drift: metrics.json `weighted_gain_search.encoder_gain`,
// `.gyro_gain`, `.drift_percent`, `.unit_drift_percent` (gains 1/1), plus the run's own outputs.
int WeightedGainProtocol(const ProtocolContext& context);
// Reads the `weighted_gain_search:` section as the protocol does. @throws sim::ConfigError.
void CheckWeightedGainOptions(const sim::ExperimentConfig& config);

}  // namespace plywood::eval
