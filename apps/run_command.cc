#include "apps/run_command.h"

#include "apps/command_line.h"
#include "eval/protocol.h"
#include "sim/config/experiment_config.h"

namespace plywood::apps {

int RunCommand(const std::vector<std::string>& args) {
  const CommandLine line(args, {"--out", "--seed", "--set"}, {"--quiet", "--no-snapshot"});
  if (line.positional().size() != 1) {
    throw UsageError{
        "usage: plywood run EXPERIMENT.yaml [--out DIR] [--seed N] [--set key=value]..."};
  }
  std::vector<std::string> overrides = line.Values("--set");
  if (const auto seed = line.Value("--seed")) overrides.push_back("seed=" + *seed);
  const sim::ExperimentConfig config = sim::LoadExperimentConfig(line.positional()[0], overrides);
  const std::string out_dir =
      line.Value("--out").value_or("runs/" + config.name + "-seed" + std::to_string(config.seed));
  const bool snapshots = config.output.snapshot && !line.Switch("--no-snapshot");
  return eval::RunProtocol(
      eval::ProtocolContext{config, out_dir, line.Switch("--quiet"), snapshots});
}

}  // namespace plywood::apps
