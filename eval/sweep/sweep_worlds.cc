#include "eval/sweep/sweep_worlds.h"

#include "sim/config/config_error.h"

namespace plywood::eval {

std::vector<SweepWorld> PrepareSweepWorlds(const SweepSpec& spec,
                                           const std::filesystem::path& /*out_dir*/) {
  std::vector<SweepWorld> worlds;
  for (const auto& path : spec.world_files) worlds.push_back({path, ""});
  for (const auto& generated : spec.generated) {
    // TODO(lead): the world generator (sim/world/generator) lands with helper D.
    throw sim::ConfigError(spec.source_file, "worlds.family",
                           "unknown family '" + generated.family + "'");
  }
  return worlds;
}

}  // namespace plywood::eval
