// Experiment YAML (sim/config/experiment_config.h), resolved against experiments/: a config that
// loads writes a config.yaml that loads back to the same config (the same YAML again).
#include "fuzz/fuzz_support.h"
#include "fuzz/fuzz_target.h"
#include "plywood_paths.h"
#include "sim/config/config_error.h"
#include "sim/config/experiment_config.h"

namespace plywood::fuzz {
namespace {

void FuzzExperimentYaml(std::span<const std::uint8_t> data) {
  const std::string text = AsText(data);
  // A plugins: list loads shared libraries into the fuzzer: not a parser's business.
  if (text.find("plugins") != std::string::npos) return;
  const std::filesystem::path base_dir = std::filesystem::path(PLYWOOD_SOURCE_ROOT) / "experiments";
  const std::string source = "fuzz_experiment.yaml";
  std::string written;
  try {
    written = sim::ExperimentConfigToYaml(sim::ParseExperimentConfig(text, source, base_dir));
  } catch (const sim::ConfigError& e) {
    RequireCleanError(e, source);
    return;
  }
  try {
    const std::string again =
        sim::ExperimentConfigToYaml(sim::ParseExperimentConfig(written, "config.yaml", base_dir));
    Require(again == written,
            "config.yaml loads back to another config:\n" + written + "\n--- then ---\n" + again);
  } catch (const sim::ConfigError& e) {
    Require(false, std::string("config.yaml does not load back: ") + e.what() + "\n" + written);
  }
}

}  // namespace
}  // namespace plywood::fuzz

PLYWOOD_FUZZ_TARGET("experiment_yaml", plywood::fuzz::FuzzExperimentYaml)
