// Sweep files (eval/sweep/sweep_spec.h), read from a scratch folder (relative paths then resolve
// against the data root): loads or refuses with one line naming the file.
#include "eval/sweep/sweep_spec.h"
#include "fuzz/fuzz_support.h"
#include "fuzz/fuzz_target.h"
#include "sim/config/config_error.h"

namespace plywood::fuzz {
namespace {

void FuzzSweepYaml(std::span<const std::uint8_t> data) {
  const std::filesystem::path path = WriteScratchFile("fuzz.sweep.yaml", data);
  try {
    const eval::SweepSpec spec = eval::LoadSweepSpec(path);
    Require(!spec.experiments.empty(), "a sweep without an experiment was accepted");
    for (const eval::GeneratedWorlds& worlds : spec.generated) {
      Require(worlds.count > 0, "a generated family of no worlds was accepted");
    }
  } catch (const sim::ConfigError& e) {
    RequireCleanError(e, path.string());
  }
}

}  // namespace
}  // namespace plywood::fuzz

PLYWOOD_FUZZ_TARGET("sweep_yaml", plywood::fuzz::FuzzSweepYaml)
