#pragma once

#include <filesystem>
#include <string>

namespace plywood::testing {

// What the CI gates of seed 001's map read from a run's metrics.json.
struct SonarMapScore {
  double error = 0.0;       // occupancy.error: e of the partition map
  double grid_error = 0.0;  // occupancy.grid_error
  double contacts = 0.0;    // sensors.bumpers.contact_samples
  std::string end_reason;   // exploration.end_reason
};

// Runs `plywood run experiments/<experiment> --quiet --out <out> <extra_args>` (the run's stdout
// and stderr go to out's parent) and reads its scores; a failed run fails the calling test
// (ASSERT inside: check HasFatalFailure() after the call).
SonarMapScore RunSonarMap(const std::string& experiment, const std::filesystem::path& out,
                          const std::string& extra_args = "");

}  // namespace plywood::testing
