#include "eval/score/rerun_world_check.h"

#include "eval/score/run_directory.h"
#include "eval/score/run_world_check.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"
#include "sim/runner/run_directory.h"

namespace plywood::eval {

void RequireWorldOfARerunUnchanged(const std::filesystem::path& experiment,
                                   const std::vector<std::string>& overrides) {
  namespace fs = std::filesystem;
  if (experiment.filename() != "config.yaml") return;
  // `--set world=W.xml` says which world to run in: the run's own is not asked for.
  for (const std::string& assignment : overrides) {
    if (assignment.substr(0, assignment.find('=')) == "world") return;
  }
  const fs::path dir = experiment.has_parent_path() ? experiment.parent_path() : fs::path(".");
  std::error_code error;
  // An edited config.yaml (its size no longer complete.json's) is an experiment of its own.
  if (!fs::is_regular_file(dir / "walls.csv", error) || !sim::WhyNotAFinishedRun(dir).empty()) {
    return;
  }
  const sim::ExperimentConfig config = sim::LoadExperimentConfig(experiment, {});
  // A protocol's walls.csv holds the walls of each of its rooms (seed000_rooms), or none.
  if (config.protocol != "single") return;
  const sim::ExperimentRunner runner(config);  // the scene as the run built it; nothing runs
  RequireWorldAsTheRunSawIt(runner.scene(), config, ReadWallsCsv(dir / "walls.csv"), experiment,
                            "running it would not repeat the run: restore the world, or give "
                            "--set world=" +
                                config.world_path.string() + " to run in it as it is now");
}

}  // namespace plywood::eval
