#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace plywood::eval {

// `plywood run RUN/config.yaml` repeats the run exactly (docs/run_outputs.md) only while the world
// file config.yaml names is as the run saw it: after an edit (a wall moved) it ran another run,
// exit 0, its walls.csv and snapshot different, without a word. When `experiment` is the
// config.yaml of a finished single run with its walls.csv beside it, and no override gives `world`,
// the world must still give the run's walls (RequireWorldAsTheRunSawIt).
// @throws sim::ConfigError naming config.yaml's `world` and the first wall that differs.
void RequireWorldOfARerunUnchanged(const std::filesystem::path& experiment,
                                   const std::vector<std::string>& overrides);

}  // namespace plywood::eval
