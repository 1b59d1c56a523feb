// The end of a run between two odometry samples: the runner reads the encoders and the gyro once
// more at the final instant, so the last trajectory row pairs the truth with estimates of the same
// instant. Judged against the closed form of ideal sensors: a gyro's integrated heading equals the
// true heading change exactly, whenever the robot stops.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

#include "msgs/pose2d.h"
#include "plywood_paths.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"
#include "sim/runner/run_observer.h"

namespace plywood::sim {
namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

// Spins the robot on the spot at a constant wheel speed and ends the run at `end_s`.
class SpinAndStop : public RunObserver {
 public:
  explicit SpinAndStop(double end_s) : end_s_(end_s) {}
  bool AfterStep(const ExperimentRunner& runner) override {
    return runner.scene().time_s() < end_s_ - 1e-9;
  }
  std::optional<msgs::WheelSpeedCommand> WheelOverride() override {
    return msgs::WheelSpeedCommand{.left_rad_s = -2.0, .right_rad_s = 2.0};
  }

 private:
  double end_s_;
};

TEST(FinalOdometryReadSimTest, IdealGyroEndsWithTheTrueHeadingOffTheSampleGrid) {
  const std::string yaml =
      "name: final_odometry_read\n"
      "seed: 3\n"
      "duration_s: 10\n"
      "world: worlds/hall.xml\n"
      "robot: {model: p3dx, spawn: {x_m: 0, y_m: 0, theta_deg: 0}}\n"
      "controller: {type: idle}\n"
      "sensors:\n"
      "  encoders: {}\n"
      "  gyro: {noise_sigma_rad_s: 0}\n"
      "odometry:\n"
      "  gyro: {}\n"
      "output: {snapshot: false, sensor_logs: false}\n";
  const ExperimentConfig config =
      ParseExperimentConfig(yaml, "inline", std::filesystem::path(PLYWOOD_SOURCE_ROOT));
  // 10 Hz odometry: samples at 2.0 and 2.1 s; the run ends 30 ms after the one at 2.0 s.
  const double end_s = 2.03;
  ExperimentRunner runner(config);
  SpinAndStop observer(end_s);
  runner.SetObserver(&observer);
  runner.Run();

  const RunRecord& record = runner.record();
  const double final_s = runner.scene().time_s();
  ASSERT_NEAR(final_s, end_s, 1e-9);
  // The truth turned by more than a degree since the last scheduled sample (what the estimates
  // missed before the final read)...
  const msgs::Pose2D& last = record.trajectory.back().truth;
  const msgs::Pose2D& previous = record.trajectory[record.trajectory.size() - 2].truth;
  ASSERT_NEAR(record.trajectory[record.trajectory.size() - 2].time_s, 2.0, 1e-9);
  EXPECT_GT(std::abs(msgs::WrapAngle(last.theta_rad - previous.theta_rad)) * kRadToDeg, 1.0);
  // ...and both odometry sensors were read at the final instant, so the ideal gyro's heading is the
  // true one.
  EXPECT_EQ(record.trajectory.back().time_s, final_s);
  EXPECT_EQ(record.encoders.back().time_s, final_s);
  EXPECT_EQ(record.gyro.back().time_s, final_s);
  EXPECT_NEAR(record.metrics.Number("odometry.gyro.heading_error_deg"), 0.0, 1e-6);
  EXPECT_NEAR(msgs::WrapAngle(record.trajectory.back().estimates[0].theta_rad - last.theta_rad),
              0.0, 1e-8);
}

}  // namespace
}  // namespace plywood::sim
