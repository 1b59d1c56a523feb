// Issue 18: bad setups that used to run to the end with exit 0 (or crash) are refused up front
// with one line `plywood: FILE: FIELD: what is wrong` and exit code 2, and write no results.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "perception/logs/carmen_log.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing::MakeTempDir;
using testing::RunPlywood;
using testing::Slurp;
using testing::WriteFile;

// A P3-DX in the 8 x 8 m hall (inner walls at +-4 m), facing +x.
std::string HallExperiment(double x_m, double y_m, const std::string& extra = "",
                           const std::string& sensors = "{encoders: {}}") {
  return "name: hall_spawn\n"
         "duration_s: 0.5\n"
         "world: worlds/hall.xml\n"
         "robot: {model: p3dx, spawn: {x_m: " +
         std::to_string(x_m) + ", y_m: " + std::to_string(y_m) +
         ", theta_deg: 0}}\n"
         "sensors: " +
         sensors +
         "\n"
         "output: {snapshot: false}\n" +
         extra;
}

// The seed 001 room with an obstacle against the north wall (obstacle_0: centre (0.3, 1.215),
// half-size 0.285 m), a Magellan Pro exploring it by sonar.
std::string ExplorerExperiment(double x_m, double y_m) {
  return "name: explorer\n"
         "duration_s: 0.5\n"
         "world: worlds/seed001_room_2.xml\n"
         "robot: {model: magellan_pro, spawn: {x_m: " +
         std::to_string(x_m) + ", y_m: " + std::to_string(y_m) +
         ", theta_deg: 0}}\n"
         "controller: {type: sonar_explorer, sonar_model: classical}\n"
         "sensors: {sonar: {}, encoders: {}, bumpers: {}}\n"
         "output: {snapshot: false}\n";
}

class ReliabilityTest : public ::testing::Test {
 protected:
  fs::path Dir() {
    return MakeTempDir(std::string("reliability_") +
                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }

  // Runs `yaml` with `extra_args` and checks for one line with exit 2 naming each of `must_contain`
  // and no results written.
  void ExpectRefused(const std::string& yaml, const std::string& extra_args,
                     const std::vector<std::string>& must_contain) {
    const fs::path dir = Dir();
    const fs::path file = WriteFile(dir / "experiment.yaml", yaml);
    const CliResult result = RunPlywood(
        "run " + file.string() + " --quiet --out " + (dir / "out").string() + " " + extra_args,
        dir);
    ExpectOneLine(result, must_contain);
    EXPECT_FALSE(fs::exists(dir / "out" / "metrics.json")) << "a refused run must write nothing";
  }

  static void ExpectOneLine(const CliResult& result, const std::vector<std::string>& must_contain) {
    EXPECT_EQ(result.exit_code, 2) << result.err;
    ASSERT_FALSE(result.err.empty());
    EXPECT_EQ(result.err.find('\n'), result.err.size() - 1) << "not one line: " << result.err;
    EXPECT_EQ(result.err.rfind("plywood: ", 0), 0u) << result.err;
    for (const std::string& text : must_contain) {
      EXPECT_NE(result.err.find(text), std::string::npos)
          << "expected '" << text << "' in: " << result.err;
    }
  }

  CliResult Run(const std::string& yaml, const std::string& extra_args = "") {
    const fs::path dir = Dir();
    const fs::path file = WriteFile(dir / "experiment.yaml", yaml);
    return RunPlywood(
        "run " + file.string() + " --quiet --out " + (dir / "out").string() + " " + extra_args,
        dir);
  }
};

// --- 1. Spawn pose ------------------------------------------------------------------------------

TEST_F(ReliabilityTest, SpawnInsideAHallWallIsRefused) {
  ExpectRefused(HallExperiment(4.0, 0.0), "", {"experiment.yaml", "robot.spawn", "wall_1"});
}

TEST_F(ReliabilityTest, SpawnInsideAnObstacleIsRefused) {
  // Wholly inside obstacle_0, and half across its south face.
  ExpectRefused(ExplorerExperiment(0.3, 1.215), "", {"robot.spawn", "obstacle_0"});
  ExpectRefused(ExplorerExperiment(0.3, 0.85), "", {"robot.spawn", "obstacle_0"});
}

TEST_F(ReliabilityTest, SpawnOutsideEveryRoomIsRefused) {
  ExpectRefused(HallExperiment(1e300, 0.0), "", {"robot.spawn", "outside every room"});
  // Beyond the hall's east wall, clear of it.
  ExpectRefused(HallExperiment(5.0, 0.0), "", {"robot.spawn", "outside every room"});
}

TEST_F(ReliabilityTest, SpawnFiveCentimetresFromAWallStillRuns) {
  // The P3-DX's bumper ring reaches about 0.22 m ahead of its centre of rotation; the wall's inner
  // face is at x = 4.
  double free_x = 0.0;
  for (double x = 3.60; x < 3.80; x += 0.01) {
    if (Run(HallExperiment(x, 0.0)).exit_code == 0) free_x = x;
  }
  ASSERT_GT(free_x, 3.6) << "no free spawn near the east wall";
  // The first refused spawn overlaps by under a centimetre: a spawn 5 cm back from it is free.
  EXPECT_EQ(Run(HallExperiment(free_x + 0.01, 0.0)).exit_code, 2);
  const CliResult near = Run(HallExperiment(free_x - 0.04, 0.0));
  EXPECT_EQ(near.exit_code, 0) << near.err;
}

// --- 2. Controllers and their sensors ------------------------------------------------------------

TEST_F(ReliabilityTest, WallFollowingByLaserWithTheLaserOffIsRefused) {
  ExpectRefused(HallExperiment(0.0, 0.0, "controller: {type: wall_following, sensor: laser}\n"), "",
                {"experiment.yaml", "controller.sensor", "sensors.laser"});
}

TEST_F(ReliabilityTest, WallFollowingBySonarWithTheSonarOffIsRefused) {
  ExpectRefused(HallExperiment(0.0, 0.0, "controller: {type: wall_following, sensor: sonar}\n"), "",
                {"controller.sensor", "sensors.sonar"});
}

TEST_F(ReliabilityTest, SonarExplorerWithoutSonarIsRefused) {
  ExpectRefused(ExplorerExperiment(-0.8, -0.5), "--set sensors.sonar.enabled=false",
                {"controller.type", "sensors.sonar"});
}

TEST_F(ReliabilityTest, GyroEstimatorWithoutTheGyroIsRefused) {
  ExpectRefused(HallExperiment(0.0, 0.0, "odometry: {fused: {}}\n"), "",
                {"odometry.fused", "sensors.gyro"});
}

// --- 3. Laser fov that FLASER cannot carry -------------------------------------------------------

TEST_F(ReliabilityTest, ANarrowLaserLogsBeamAnglesThatReplayReadsBack) {
  const fs::path dir = Dir();
  const fs::path file =
      WriteFile(dir / "experiment.yaml",
                HallExperiment(0.0, 0.0, "", "{encoders: {}, laser: {fov_deg: 100}}"));
  const CliResult run =
      RunPlywood("run " + file.string() + " --quiet --out " + (dir / "out").string(), dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const perception::CarmenLog log = perception::ReadCarmenLog(dir / "out" / "laser.log");
  ASSERT_FALSE(log.lasers.empty());
  const msgs::LaserScan& scan = log.lasers.front().scan;
  const double deg = std::numbers::pi / 180.0;
  EXPECT_NEAR(scan.BeamAngleRad(0), -50.0 * deg, 1e-9);
  EXPECT_NEAR(scan.BeamAngleRad(scan.ranges_m.size() - 1), 50.0 * deg, 1e-8);
  // In the hall's centre facing +x, the middle beam hits the east wall 4 m away.
  EXPECT_NEAR(scan.ranges_m[scan.ranges_m.size() / 2], 4.0 - 0.021, 0.05);

  const CliResult replay = RunPlywood(
      "replay " + (dir / "out" / "laser.log").string() + " --out " + (dir / "replay").string(),
      dir);
  EXPECT_EQ(replay.exit_code, 0) << replay.err;
  EXPECT_NE(replay.out.find("(6 scans"), std::string::npos) << replay.out;
}

// --- 4. Crashes, UB, unbounded work --------------------------------------------------------------

std::string HallWithLines() {
  return HallExperiment(0.0, 0.0, "") + "lines: {extractors: [hough]}\n";
}

TEST_F(ReliabilityTest, HoughBinsThatWouldOverflowAreRefused) {
  ExpectRefused(HallWithLines(), "--set lines.hough.rho_bin_m=1e-9",
                {"lines.hough.rho_bin_m", "1e-09"});
  ExpectRefused(HallWithLines(), "--set lines.hough.rho_bin_m=1e-7", {"lines.hough.rho_bin_m"});
  ExpectRefused(HallWithLines(), "--set lines.hough.theta_bin_deg=1e-300",
                {"lines.hough.theta_bin_deg", "1e-300"});
}

TEST_F(ReliabilityTest, SonarExplorerLengthsThatOverflowAreRefused) {
  const std::string yaml = ExplorerExperiment(-0.8, -0.5);
  for (const std::string field : {"place_size_m", "grid_half_extent_m", "visit_radius_m"}) {
    ExpectRefused(yaml, "--set controller." + field + "=1e300", {"controller." + field});
  }
  ExpectRefused(yaml, "--set controller.place_size_m=1e-9", {"controller.place_size_m", "1e-09"});
  ExpectRefused(yaml,
                "--set controller.grid_half_extent_m=100 --set controller.grid_resolution_m=0.01",
                {"controller.grid_resolution_m", "cells wide"});
}

TEST_F(ReliabilityTest, RunsOfMoreThanAHundredMillionStepsAreRefused) {
  ExpectRefused(HallExperiment(0.0, 0.0), "--set duration_s=9.3e16", {"duration_s", "steps"});
  ExpectRefused(HallExperiment(0.0, 0.0), "--set physics.timestep_s=1e-9",
                {"physics.timestep_s", "steps"});
}

// --- 5. Readers ----------------------------------------------------------------------------------

TEST_F(ReliabilityTest, ReplayOfALogWithoutScansIsRefusedNamingTheFile) {
  const fs::path dir = Dir();
  const fs::path empty = WriteFile(dir / "empty.log", "");
  ExpectOneLine(RunPlywood("replay " + empty.string() + " --out " + (dir / "r").string(), dir),
                {"empty.log", "no usable laser scan"});
  const fs::path inf = WriteFile(
      dir / "inf.log", "PARAM front_laser_max inf host 0\nFLASER 3 1 2 3 0 0 0 0 0 0 1 host 1\n");
  ExpectOneLine(RunPlywood("replay " + inf.string() + " --out " + (dir / "r").string(), dir),
                {"inf.log:1", "front_laser_max"});
}

TEST_F(ReliabilityTest, AWorldWithoutAFloorIsRefused) {
  const fs::path dir = Dir();
  const fs::path world = WriteFile(dir / "floorless.xml",
                                   "<mujoco><worldbody><geom name=\"wall\" type=\"box\" pos=\"5 0 "
                                   "0.5\" size=\"0.1 5 0.5\"/></worldbody></mujoco>\n");
  std::string yaml = HallExperiment(0.0, 0.0);
  yaml.replace(yaml.find("worlds/hall.xml"), std::string("worlds/hall.xml").size(), world.string());
  ExpectRefused(yaml, "", {"experiment.yaml", "world", "floor"});
}

TEST_F(ReliabilityTest, DuplicateKeysAreRefusedNamingTheKey) {
  ExpectRefused(HallExperiment(0.0, 0.0) + "duration_s: 2\n", "",
                {"experiment.yaml", "duration_s", "duplicate"});
  ExpectRefused(HallExperiment(0.0, 0.0, "controller: {type: idle, type: square_path}\n"), "",
                {"controller.type", "duplicate"});
}

TEST_F(ReliabilityTest, NamesThatLeaveTheRunsFolderAreRefused) {
  for (const std::string name : {"../../x", "a/b", ".."}) {
    std::string yaml = HallExperiment(0.0, 0.0);
    yaml.replace(0, yaml.find('\n'), "name: '" + name + "'");
    ExpectRefused(yaml, "", {"experiment.yaml", "name"});
  }
}

// --- 6. Error lines name the file and field, numbers in shortest form ----------------------------

TEST_F(ReliabilityTest, GridSizeErrorsNameTheControllerField) {
  // Used to read "plywood: width: must be in [1, 20000]".
  ExpectRefused(ExplorerExperiment(-0.8, -0.5), "--set controller.grid_half_extent_m=1000",
                {"experiment.yaml", "controller.grid_half_extent_m"});
}

TEST_F(ReliabilityTest, FitSigmaOutOfRangeIsRefusedBeforeTheRun) {
  // Used to end the run with "plywood: x: all points share one x".
  ExpectRefused(ExplorerExperiment(-0.8, -0.5), "--set controller.fit_sigma_m=1e300",
                {"experiment.yaml", "controller.fit_sigma_m", "1e+300"});
}

TEST_F(ReliabilityTest, TinyNumbersArePrintedInShortestForm) {
  // Used to read "got 0.000000".
  const CliResult result = Run(HallExperiment(0.0, 0.0, "") + "lines: {extractors: [hough]}\n",
                               "--set lines.hough.theta_bin_deg=1e-9");
  ExpectOneLine(result, {"1e-09"});
  EXPECT_EQ(result.err.find("0.000000"), std::string::npos) << result.err;
}

TEST_F(ReliabilityTest, RobotAndControllerLimitsArePrintedInShortestForm) {
  // Used to read "got 0.000000" (std::to_string) for each of these.
  const CliResult wall =
      Run(HallExperiment(0.0, 0.0, "controller: {type: wall_following, sensor: laser}\n",
                         "{encoders: {}, laser: {}}"),
          "--set controller.distance_m=1e-7 --set controller.max_wall_range_m=1e-8");
  ExpectOneLine(wall, {"controller.max_wall_range_m", "got 1e-08"});
  const CliResult drive = Run(HallExperiment(0.0, 0.0), "--set robot.nominal.track_m=-1e-9");
  ExpectOneLine(drive, {"robot.nominal.track_m", "got -1e-09"});
}

TEST_F(ReliabilityTest, AnUnreadableExperimentIsNotReportedAsMissing) {
  const fs::path dir = Dir();
  const fs::path folder = dir / "folder.yaml";
  fs::create_directories(folder);
  const CliResult result = RunPlywood("run " + folder.string() + " --quiet", dir);
  ExpectOneLine(result, {"folder.yaml", "not a regular file"});
  EXPECT_EQ(result.err.find("no such"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace plywood
