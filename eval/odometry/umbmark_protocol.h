#pragma once

#include "eval/protocol.h"

namespace plywood::eval {

// `protocol: umbmark` (Borenstein & Feng 1996): runs eval::RunUmbmark and writes metrics.json
// (umbmark.*), umbmark_runs.csv (every return-position error), config.yaml and, with
// umbmark.write_runs, each run's outputs under before/ and after/.
int UmbmarkProtocol(const ProtocolContext& context);
// Reads the `umbmark:` section as the protocol does. @throws sim::ConfigError.
void CheckUmbmarkOptions(const sim::ExperimentConfig& config);

}  // namespace plywood::eval
