// A replay of a run whose world file changed since the run is refused, naming config.yaml's world;
// the unchanged world passes. No window: the check needs the compiled world only.
#include "eval/score/run_world_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "eval/protocol.h"
#include "eval/score/run_directory.h"
#include "sim/config/config_error.h"
#include "sim/config/robot_catalog.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::eval {
namespace {

namespace fs = std::filesystem;

std::string Read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void Check(const fs::path& run_dir) {
  const sim::ExperimentConfig config = eval::LoadRunConfig(run_dir, "test");
  sim::SceneOptions options;
  options.world_mjcf = config.world_path;
  options.robot_mjcf = sim::FindRobot(config.robot).mjcf;
  options.spawn = {config.spawn.x_m, config.spawn.y_m, config.spawn.theta_deg * M_PI / 180.0};
  const sim::Scene scene(options);
  RequireWorldAsTheRunSawIt(scene, config, eval::ReadWallsCsv(run_dir / "walls.csv"),
                            run_dir / "config.yaml",
                            "a replay would show the run in another world");
}

TEST(RunWorldCheckTest, AWorldChangedSinceTheRunIsRefusedNamingConfigYamlsWorld) {
  const fs::path dir = testing::MakeTempDir("run_world_check");
  const fs::path world = dir / "office.xml";
  const std::string original = Read(testing::SourceRoot() / "worlds/office.xml");
  std::ofstream(world, std::ios::binary) << original;
  const fs::path run_dir = dir / "run";
  const sim::ExperimentConfig config =
      sim::LoadExperimentConfig(testing::SourceRoot() / "experiments/default.yaml",
                                {"duration_s=0.5", "world=" + world.string()});
  ASSERT_EQ(eval::RunProtocol({config, run_dir, true, false}), 0);
  EXPECT_NO_THROW(Check(run_dir));

  // The east wall 1 cm farther east: every number of the world but one as it was.
  const std::string moved =
      std::regex_replace(original, std::regex(R"(name="wall_1" class="wall" pos="8\.009 )"),
                         R"(name="wall_1" class="wall" pos="8.019 )");
  ASSERT_NE(moved, original);
  std::ofstream(world, std::ios::binary | std::ios::trunc) << moved;
  try {
    Check(run_dir);
    ADD_FAILURE() << "a replay in a changed world was accepted";
  } catch (const sim::ConfigError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind((run_dir / "config.yaml").string() + ": world: " + world.string() +
                             " changed since the run (walls.csv segment ",
                         0),
              0u)
        << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace plywood::eval
