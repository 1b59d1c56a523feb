// Seed 001's explorer in the simulator: same seed -> identical map; a corrupted weights file is a
// clear error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "perception/sonar_map/sonar_explorer.h"
#include "plywood_paths.h"
#include "sim/config/config_error.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"

namespace plywood::sim {
namespace {

const std::string kExperiment =
    std::string(PLYWOOD_SOURCE_ROOT) + "/experiments/seed001_room_4.yaml";

std::vector<double> RunMap(const std::vector<std::string>& overrides) {
  ExperimentRunner runner(LoadExperimentConfig(kExperiment, overrides));
  runner.Run();
  const auto* explorer = dynamic_cast<const perception::SonarExplorer*>(runner.controller());
  EXPECT_NE(explorer, nullptr);
  if (explorer == nullptr) return {};
  EXPECT_GT(explorer->rings_integrated(), 20);
  return explorer->grid().log_odds();
}

TEST(SonarExplorerSimTest, SameSeedGivesTheSameMap) {
  const std::vector<std::string> o{"duration_s=12"};
  const auto a = RunMap(o), b = RunMap(o);
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a, b);  // bit for bit
  int occupied = 0;
  for (double l : a) occupied += l > 1.0;
  EXPECT_GT(occupied, 10);  // the walls near the start were heard
  EXPECT_NE(RunMap({"duration_s=12", "seed=2"}), a);
}

TEST(SonarExplorerSimTest, CorruptedWeightsFileIsAClearError) {
  const auto path = std::filesystem::temp_directory_path() / "plywood_bad_sonar_net.txt";
  std::ofstream(path) << "plywood-sonar-net 1\np_clamp 0.02\nlayers 1\nlayer 1 5\n0.1 0.2 oops\n";
  try {
    ExperimentRunner runner(
        LoadExperimentConfig(kExperiment, {"controller.weights_file=" + path.string()}));
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()), kExperiment + ": controller: weights_file: " + path.string() +
                                         ": line 5: 'oops' is not a finite number");
  }
}

}  // namespace
}  // namespace plywood::sim
