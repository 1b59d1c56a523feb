// Every experiment shipped in experiments/ loads, validates and runs (briefly), so a renamed key
// or a moved world can never break what users start from.

#include <gtest/gtest.h>

#include <filesystem>

#include "eval/sweep/sweep_cells.h"
#include "eval/sweep/sweep_spec.h"
#include "eval/sweep/sweep_worlds.h"
#include "perception/logs/carmen_log.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"
#include "sim/runner/run_writer.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;

TEST(ShippedExperimentsTest, EveryExperimentRunsTwoSimulatedSeconds) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(testing::SourceRoot() / "experiments")) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    ++count;
    const sim::ExperimentConfig config =
        sim::LoadExperimentConfig(entry.path(), {"duration_s=2", "output.snapshot=false"});
    sim::ExperimentRunner runner(config);
    runner.Run();
    EXPECT_NEAR(runner.record().trajectory.back().time_s, 2.0, 1e-6);
    EXPECT_EQ(runner.record().metrics.Number("run.steps"),
              std::round(2.0 / config.physics.timestep_s));
  }
  EXPECT_GE(count, 3);
}

TEST(ShippedExperimentsTest, SimulatedLaserLogReadsBackThroughTheRealLogReader) {
  const sim::ExperimentConfig config = sim::LoadExperimentConfig(
      testing::SourceRoot() / "experiments" / "default.yaml", {"duration_s=1"});
  sim::ExperimentRunner runner(config);
  runner.Run();
  const fs::path dir = testing::MakeTempDir("SimulatedLaserLog");
  sim::WriteRunOutputs(config, runner.record(), dir);
  const perception::CarmenLog log = perception::ReadCarmenLog(dir / "laser.log");
  ASSERT_EQ(log.lasers.size(), runner.record().laser.size());
  EXPECT_EQ(log.params.at("front_laser_max"), "8");
  for (std::size_t s = 0; s < log.lasers.size(); ++s) {
    const msgs::LaserScan& written = runner.record().laser[s].scan;
    const msgs::LaserScan& read = log.lasers[s].scan;
    ASSERT_EQ(read.ranges_m.size(), 361u);
    EXPECT_NEAR(read.angle_increment_rad, written.angle_increment_rad, 1e-12);
    EXPECT_NEAR(read.angle_min_rad, written.angle_min_rad, 1e-12);
    for (std::size_t i = 0; i < read.ranges_m.size(); ++i) {
      // The log keeps millimetres, the LMS 200's own resolution in its 8 m mode.
      EXPECT_NEAR(read.ranges_m[i], std::min(written.ranges_m[i], written.range_max_m), 5e-4);
    }
    const msgs::Pose2D X_WL = runner.record().laser[s].X_WR_truth * written.X_RS;
    EXPECT_NEAR(log.lasers[s].X_WL.x_m, X_WL.x_m, 1e-6);
    EXPECT_NEAR(log.lasers[s].X_WL.y_m, X_WL.y_m, 1e-6);
  }
}

// The walk-through sweep is what a newcomer runs first: its runs must drive their tour in the
// world it names, not press the robot into a wall (the office's waypoints in the hall did: 166
// contact samples in 30 s, 2.45 m travelled).
TEST(ShippedExperimentsTest, TheMinimalSweepDrivesItsTourClearOfTheWalls) {
  const eval::SweepSpec spec =
      eval::LoadSweepSpec(testing::SourceRoot() / "experiments" / "sweeps" / "minimal.yaml");
  const auto worlds = eval::PrepareSweepWorlds(spec, testing::MakeTempDir("MinimalSweep"), true);
  const std::vector<eval::SweepCell> cells = eval::ExpandCells(spec, worlds);
  ASSERT_EQ(cells.size(), 12u);
  for (const eval::SweepCell& cell : cells) {
    SCOPED_TRACE(cell.id);
    std::vector<std::string> overrides = cell.overrides;
    overrides.push_back("output.snapshot=false");
    const sim::ExperimentConfig config = sim::LoadExperimentConfig(cell.experiment, overrides);
    sim::ExperimentRunner runner(config);
    runner.Run();
    const auto& metrics = runner.record().metrics;
    EXPECT_EQ(metrics.Number("sensors.bumpers.contact_samples"), 0.0);
    // Most of the time at the tour's 0.4 m/s (the rest: turns at the corners).
    EXPECT_GT(metrics.Number("truth.distance_m"), 0.3 * config.duration_s);
  }
}

}  // namespace
}  // namespace plywood
