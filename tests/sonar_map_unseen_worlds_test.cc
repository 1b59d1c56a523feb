// CI gate for seed 001's map on rooms that are not in the repo: writes each room of
// tests/baselines/sonar_map_unseen.json as MJCF, explores it with its layout's shipped experiment
// and fails when e or the grid's e rises above the measured value plus the margin, or when the
// robot touches something it did not touch before. Two rooms pin a fixed defect: the explorer
// finished with a third of the room unknown because it stood on a frontier goal already.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"
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

// A floor and plywood walls 18 mm thick with their inner faces on x = +-w/2, y = +-h/2.
std::string FloorAndWalls(double w, double h) {
  const double t = 0.009;
  std::ostringstream s;
  s << "<geom name=\"floor\" type=\"plane\" size=\"" << w / 2 + 0.5 << " " << h / 2 + 0.5
    << " 0.05\"/>\n"
    << Box("wall_0", 0, -h / 2 - t, w / 2 + 2 * t, t, 0.5)
    << Box("wall_1", w / 2 + t, 0, t, h / 2, 0.5)
    << Box("wall_2", 0, h / 2 + t, w / 2 + 2 * t, t, 0.5)
    << Box("wall_3", -w / 2 - t, 0, t, h / 2, 0.5);
  return s.str();
}

// A room of the baseline file; boxes 0.6 m tall.
std::string RoomMjcf(const YAML::Node& room) {
  const double w = room["room"][0].as<double>(), h = room["room"][1].as<double>();
  std::ostringstream s;
  s << "<mujoco model=\"unseen_room\"><worldbody>\n" << FloorAndWalls(w, h);
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

// Issue 14 round 24: the only way into a room's far part is a gap wider than the robot (0.41 m)
// that the cells heard narrow to less than twice narrow_clearance_m (0.7 m), so no frontier path
// keeps 0.35 m from them; the last frontier tier, squeeze_clearance_m (0.3 m), drives through.
// Here a partition 0.3 m thick crosses a 3.4 x 3.0 m room 1.4 m from its east wall, with a 0.62 m
// opening; the robot starts east of it. Measured (stop 52): every seed 1-3 crosses, e 0.008-0.010,
// complete at 175-186 s; with squeeze_clearance_m 0 seed 3 stays east (e 0.077, complete at
// 122 s). Until stop 51 this test ran generator seed 9's world 5, a 0.61 m gap between two boxes
// met at a slant: with the sensors in step the front check hears the north box's corner 0.19 m
// beside the path and gives the move up (e 0.046 -> 0.082; docs/sonar_map/history.md, stop 52).
std::string PartitionedRoomMjcf(double gap_m) {
  const double w = 3.4, h = 3.0, x = 0.3, centre_y = 0.3;
  const double lo = centre_y - gap_m / 2.0, hi = centre_y + gap_m / 2.0;
  std::ostringstream s;
  s << "<mujoco model=\"partitioned_room\"><worldbody>\n"
    << FloorAndWalls(w, h) << Box("obstacle_0", x, (lo - h / 2) / 2, 0.15, (lo + h / 2) / 2, 0.3)
    << Box("obstacle_1", x, (hi + h / 2) / 2, 0.15, (h / 2 - hi) / 2, 0.3)
    << "</worldbody></mujoco>\n";
  return s.str();
}

TEST(SonarMapUnseenWorldsTest, AGapWiderThanTheRobotIsDrivenThrough) {
  const fs::path dir = MakeTempDir("sonar_map_squeeze");
  const fs::path world = dir / "partitioned_room.xml";
  std::ofstream(world) << PartitionedRoomMjcf(0.62);
  for (const int seed : {1, 2, 3}) {
    const fs::path out = dir / ("run_" + std::to_string(seed));
    const SonarMapScore score = RunSonarMap(
        "seed001_room_1.yaml", out,
        "--seed " + std::to_string(seed) + " --set world=" + world.string() +
            " --set robot.spawn.x_m=1.1 --set robot.spawn.y_m=0 --set robot.spawn.theta_deg=180");
    ASSERT_FALSE(::testing::Test::HasFatalFailure());
    // How far west the robot truly went: past the partition's west face (x = 0.15) by a body.
    std::ifstream trajectory(out / "trajectory.csv");
    std::string line;
    std::getline(trajectory, line);
    ASSERT_EQ(line.rfind("time_s,truth_x_m,", 0), 0u) << line;
    double west_m = 1e9;
    while (std::getline(trajectory, line)) {
      const std::size_t comma = line.find(',');
      west_m = std::min(west_m, std::stod(line.substr(comma + 1)));
    }
    std::printf("seed %d: e %.4f grid e %.4f, %s, westmost x %.2f m\n", seed, score.error,
                score.grid_error, score.end_reason.c_str(), west_m);
    EXPECT_LT(west_m, -0.5) << "seed " << seed;
    EXPECT_LE(score.error, 0.03) << "seed " << seed;
    EXPECT_EQ(score.end_reason, "map_complete") << "seed " << seed;
    // Seeds 1 and 3 brush the opening's south edge for one 10 Hz bumper sample at x 0.29-0.31 m,
    // driving ~0.19 m/s (main's code before the sensor-step mend too, seeds 2 and 3): issue 14 asks
    // no contact of the four layouts; more than a brush is a defect here.
    EXPECT_LE(score.contacts, 1.0) << "seed " << seed;
  }
}

// Issue 14 round 58b (controller.complete_room_check): generator seed 76's world 26 (worked on)
// starts in a pocket of boxes whose exits are 0.45-0.58 m wide. At seed 3 a blocked move gives its
// goal up at 21.8 s and the last frontier lies within the exclusion; the room is fitted on the
// east box's face, so round 42a's unknown share reads 0.393 and the run ends with e 0.7136. With
// the sides past which the robot saw a body-wide patch of floor opened, the share reads 0.807, the
// given-up goal is retried and the run goes on to 64 s (measured at stop 58: e 0.0844, no contact).
TEST(SonarMapUnseenWorldsTest, ARoomFittedOnABoxFaceIsNotCompleteWhileFloorWasSeenPastIt) {
  const fs::path dir = MakeTempDir("sonar_map_box_face_room");
  const testing::CliResult generated = testing::RunPlywood(
      "worlds generate seed001 --count 27 --seed 76 --quiet --out " + (dir / "worlds").string(),
      dir);
  ASSERT_EQ(generated.exit_code, 0) << generated.err;
  const fs::path world = dir / "worlds" / "seed001_s76_00026.xml";
  const SonarMapScore score = RunSonarMap(
      "seed001_room_1.yaml", dir / "run",
      "--seed 3 --set world=" + world.string() +
          " --set robot.spawn.x_m=0 --set robot.spawn.y_m=0 --set robot.spawn.theta_deg=100"
          " --set output.snapshot=false --set controller.complete_room_check=true");
  ASSERT_FALSE(::testing::Test::HasFatalFailure());
  std::printf("e %.4f grid e %.4f, %s, contact samples %.0f\n", score.error, score.grid_error,
              score.end_reason.c_str(), score.contacts);
  EXPECT_LE(score.error, 0.10);
  EXPECT_EQ(score.end_reason, "map_complete");
  EXPECT_EQ(score.contacts, 0.0);
}

// Issue 14 round 64a: held-out generator seed 69, world 22, run seed 2 (e 0.2985, the held-out
// worst). The perimeter ends stuck at the spawn and the robot never passes two boxes whose west
// faces (x = 1.56 m) the line fit takes for the room's east side; the floor seen past them in the
// gaps beside them says they are not the wall. With open_sides_seen_past_m the reported room is
// opened there and the floor behind the faces is mapped free; the run itself is the same.
TEST(SonarMapUnseenWorldsTest, ARoomSideOnBoxFacesWithFloorSeenPastThemIsOpenedWhenAsked) {
  const fs::path dir = MakeTempDir("sonar_map_open_sides");
  const testing::CliResult generated = testing::RunPlywood(
      "worlds generate seed001 --count 23 --seed 69 --quiet --out " + (dir / "worlds").string(),
      dir);
  ASSERT_EQ(generated.exit_code, 0) << generated.err;
  const std::string args =
      "--seed 2 --set world=" + (dir / "worlds" / "seed001_s69_00022.xml").string() +
      " --set robot.spawn.x_m=0 --set robot.spawn.y_m=0"
      " --set robot.spawn.theta_deg=163 --set output.snapshot=false";
  const SonarMapScore fitted = RunSonarMap("seed001_room_1.yaml", dir / "fitted",
                                           args + " --set controller.open_sides_seen_past_m=0");
  ASSERT_FALSE(::testing::Test::HasFatalFailure());
  const SonarMapScore opened = RunSonarMap("seed001_room_1.yaml", dir / "opened",
                                           args + " --set controller.open_sides_seen_past_m=0.4");
  ASSERT_FALSE(::testing::Test::HasFatalFailure());
  std::printf("e %.4f -> %.4f (grid e %.4f / %.4f), contact samples %.0f / %.0f\n", fitted.error,
              opened.error, fitted.grid_error, opened.grid_error, fitted.contacts, opened.contacts);
  EXPECT_GT(fitted.error, 0.25);
  EXPECT_LE(opened.error, 0.15);
  // The option changes the map the robot reports, not where it went.
  EXPECT_EQ(opened.grid_error, fitted.grid_error);
  EXPECT_EQ(opened.contacts, fitted.contacts);
}

// Question 6 to steering: a 3 x 3 m room with a 1.0 x 0.5 m box whose south face is 0.30 m from
// the south wall. The gap is narrower than the Magellan Pro (0.429 m across its bumper ring), so
// occupancy.area_narrow_gaps_m2 is the gap's 0.30 m^2 (to a row or column of 1 cm cells), and
// leaving it unscored can only take error area away: e' (A_tot - A_gap) <= e A_tot.
TEST(SonarMapUnseenWorldsTest, AGapNarrowerThanTheRobotIsLeftUnscoredBesideE) {
  const fs::path dir = MakeTempDir("sonar_map_narrow_gap");
  const fs::path world = dir / "narrow_gap_room.xml";
  std::ofstream(world) << "<mujoco model=\"narrow_gap_room\"><worldbody>\n"
                       << FloorAndWalls(3.0, 3.0) << Box("obstacle_0", 0.0, -0.95, 0.5, 0.25, 0.3)
                       << "</worldbody></mujoco>\n";
  const fs::path out = dir / "run";
  const SonarMapScore score = RunSonarMap(
      "seed001_room_1.yaml", out,
      "--set world=" + world.string() +
          " --set robot.spawn.x_m=0 --set robot.spawn.y_m=0.8 --set robot.spawn.theta_deg=0"
          " --set output.snapshot=false");
  ASSERT_FALSE(::testing::Test::HasFatalFailure());
  const YAML::Node occupancy = YAML::LoadFile((out / "metrics.json").string())["occupancy"];
  const double total_m2 = occupancy["area_total_m2"].as<double>();
  const double gap_m2 = occupancy["area_narrow_gaps_m2"].as<double>();
  const double without = occupancy["error_without_narrow_gaps"].as<double>();
  std::printf("e %.4f, without the narrow gap %.4f, gap %.4f m^2 of %.4f\n", score.error, without,
              gap_m2, total_m2);
  EXPECT_NEAR(gap_m2, 0.30, 0.011);
  EXPECT_LE(without * (total_m2 - gap_m2), score.error * total_m2 + 1e-9);
}

}  // namespace
}  // namespace plywood
