#pragma once

#include <filesystem>
#include <vector>

#include "eval/sweep/sweep_cells.h"
#include "eval/sweep/sweep_spec.h"

namespace plywood::eval {

// The worlds a sweep runs in: its files as given, or the generator's worlds, written once into
// OUT/worlds/<family>-seed<S>/ (byte-identical on every call, so a resumed sweep finds the same;
// a set edited by hand is written anew, saying so unless `quiet`).
// @throws sim::ConfigError naming worlds.family for an unknown family.
std::vector<SweepWorld> PrepareSweepWorlds(const SweepSpec& spec,
                                           const std::filesystem::path& out_dir, bool quiet);

}  // namespace plywood::eval
