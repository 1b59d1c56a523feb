// CI gate for seed 001's map on rooms that are not in the repo: writes each room of
// tests/baselines/sonar_map_unseen.json as MJCF, explores it with its layout's shipped experiment
// and fails when e or the grid's e rises above the measured value plus the margin, or when the
// robot touches something it did not touch before. Two rooms pin a fixed defect: the explorer
// finished with a third of the room unknown because it stood on a frontier goal already.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sim/world/generator/world_generator.h"
#include "tests/support/mujoco_test_support.h"
#include "tests/support/sonar_map_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;
using testing::MakeTempDir;
using testing::RunSonarMap;
using testing::SonarMapScore;
using testing::SourceRoot;

std::string Box(const std::string& name, double x, double y, double hx, double hy, double hz) {
  std::ostringstream s;
  s << "<geom name=\"" << name << "\" type=\"box\" pos=\"" << x << " " << y << " " << hz
    << "\" size=\"" << hx << " " << hy << " " << hz << "\"/>\n";
  return s.str();
}

// Plywood walls 18 mm thick with their inner faces on x = +-w/2, y = +-h/2; boxes 0.6 m tall.
std::string RoomMjcf(const YAML::Node& room) {
  const double w = room["room"][0].as<double>(), h = room["room"][1].as<double>();
  const double t = 0.009;
  std::ostringstream s;
  s << "<mujoco model=\"unseen_room\"><worldbody>\n"
    << "<geom name=\"floor\" type=\"plane\" size=\"" << w / 2 + 0.5 << " " << h / 2 + 0.5
    << " 0.05\"/>\n"
    << Box("wall_0", 0, -h / 2 - t, w / 2 + 2 * t, t, 0.5)
    << Box("wall_1", w / 2 + t, 0, t, h / 2, 0.5)
    << Box("wall_2", 0, h / 2 + t, w / 2 + 2 * t, t, 0.5)
    << Box("wall_3", -w / 2 - t, 0, t, h / 2, 0.5);
  int i = 0;
  for (const auto& b : room["boxes"])
    s << Box("obstacle_" + std::to_string(i++), b[0].as<double>(), b[1].as<double>(),
             b[2].as<double>(), b[3].as<double>(), 0.3);
  s << "</worldbody></mujoco>\n";
  return s.str();
}

TEST(SonarMapUnseenWorldsTest, MapErrorDoesNotWorsen) {
  const YAML::Node baseline =
      YAML::LoadFile((SourceRoot() / "tests" / "baselines" / "sonar_map_unseen.json").string());
  const double margin = baseline["margin"].as<double>();
  const fs::path dir = MakeTempDir("sonar_map_unseen");
  for (const auto& entry : baseline["worlds"]) {
    const std::string name = entry.first.as<std::string>();
    const YAML::Node& room = entry.second;
    const fs::path world = dir / (name + ".xml");
    std::ofstream(world) << RoomMjcf(room);
    const YAML::Node& spawn = room["spawn"];
    const std::string experiment =
        "seed001_room_" + std::to_string(room["layout"].as<int>()) + ".yaml";
    const SonarMapScore score = RunSonarMap(
        experiment, dir / name,
        "--set world=" + world.string() + " --set robot.spawn.x_m=" + spawn[0].as<std::string>() +
            " --set robot.spawn.y_m=" + spawn[1].as<std::string>() +
            " --set robot.spawn.theta_deg=" + spawn[2].as<std::string>());
    ASSERT_FALSE(::testing::Test::HasFatalFailure());
    std::printf("%s (layout %d) e %.4f grid e %.4f contact samples %.0f\n", name.c_str(),
                room["layout"].as<int>(), score.error, score.grid_error, score.contacts);
    EXPECT_LE(score.error, room["error"].as<double>() + margin) << name;
    EXPECT_LE(score.grid_error, room["grid_error"].as<double>() + margin) << name;
    EXPECT_LE(score.contacts, room["contacts"].as<double>()) << name;
  }
}

// Issue 14 round 24: generator seed 9, world 5 (seed 1). The only way into the room's far part is a
// gap wider than the robot (0.41 m) that the cells heard narrow to less than twice
// narrow_clearance_m (0.7 m): no frontier path kept 0.35 m from them, the explorer declared the
// map complete at 84 s and the map guessed the part it never saw (e 0.103). With the last
// frontier tier at squeeze_clearance_m (0.3 m) it drives through: e 0.046, complete at 158 s.
TEST(SonarMapUnseenWorldsTest, AGapWiderThanTheRobotIsDrivenThrough) {
  const fs::path dir = MakeTempDir("sonar_map_squeeze");
  sim::worldgen::GenerateWorldsOptions options;
  options.family = "seed001";
  options.count = 6;
  options.seed = 9;
  options.out_dir = dir / "worlds";
  const std::vector<sim::worldgen::GeneratedWorldFile> files =
      sim::worldgen::GenerateWorlds(options);
  ASSERT_EQ(files.size(), 6u);
  const sim::worldgen::GeneratedWorld world = sim::worldgen::GenerateWorld("seed001", 9, 5);
  ASSERT_FALSE(world.spawns.empty());
  const sim::worldgen::SpawnPose& spawn = world.spawns.front();
  const SonarMapScore score =
      RunSonarMap("seed001_room_1.yaml", dir / "run",
                  "--set world=" + files[5].mjcf.string() +
                      " --set robot.spawn.x_m=" + std::to_string(spawn.x_m) +
                      " --set robot.spawn.y_m=" + std::to_string(spawn.y_m) +
                      " --set robot.spawn.theta_deg=" + std::to_string(spawn.yaw_deg));
  ASSERT_FALSE(::testing::Test::HasFatalFailure());
  std::printf("generator seed 9 world 5: e %.4f grid e %.4f, %s\n", score.error, score.grid_error,
              score.end_reason.c_str());
  EXPECT_LE(score.error, 0.046 + 0.01);
  EXPECT_EQ(score.end_reason, "map_complete");
  EXPECT_EQ(score.contacts, 0.0);
}

}  // namespace
}  // namespace plywood
