#pragma once

#include <filesystem>

namespace plywood::sim {

// Whether `dir` holds an earlier Plywood run: its config.yaml starts with "name: ", as every run
// directory's does (the resolved experiment, or the record of a replay).
bool HoldsPlywoodRun(const std::filesystem::path& dir);

// Makes `dir` ready to receive a run's results, before anything is simulated:
//   - absent or empty: nothing to do (the writers create it);
//   - an earlier Plywood run (HoldsPlywoodRun): refused unless `force`; with `force` everything in
//     it is removed, so no file of the earlier run survives beside the new one;
//   - anything else that is not empty, or not a directory: refused, even with `force` (a user's
//     own files are never deleted).
// @throws sim::ConfigError naming `dir` (one line, exit code 2 in the apps) when refused.
void PrepareRunDirectory(const std::filesystem::path& dir, bool force);

}  // namespace plywood::sim
