// A wheel command that is not a number: MuJoCo (and the planar drive) would zero it and the robot
// would stand still with no word said; the runner ends the run with a one-line error instead.

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "plywood_paths.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"
#include "sim/runner/run_observer.h"

namespace plywood::sim {
namespace {

// Drives straight until `bad_from_s`, then commands a NaN left wheel.
class TurnsNaN : public RunObserver {
 public:
  explicit TurnsNaN(double bad_from_s) : bad_from_s_(bad_from_s) {}
  bool AfterStep(const ExperimentRunner& runner) override {
    time_s_ = runner.scene().time_s();
    return true;
  }
  std::optional<msgs::WheelSpeedCommand> WheelOverride() override {
    const double left =
        time_s_ < bad_from_s_ - 1e-9 ? 2.0 : std::numeric_limits<double>::quiet_NaN();
    return msgs::WheelSpeedCommand{.left_rad_s = left, .right_rad_s = 2.0};
  }

 private:
  double bad_from_s_;
  double time_s_ = 0.0;
};

ExperimentConfig Config(const std::string& drive) {
  const std::string yaml =
      "name: non_finite_command\n"
      "seed: 1\n"
      "duration_s: 2\n"
      "world: worlds/hall.xml\n"
      "robot: {model: p3dx, spawn: {x_m: 0, y_m: 0, theta_deg: 0}}\n"
      "controller: {type: idle}\n"
      "sensors: {encoders: {}}\n"
      "physics: {drive: " +
      drive +
      "}\n"
      "output: {snapshot: false, sensor_logs: false}\n";
  return ParseExperimentConfig(yaml, "inline", std::filesystem::path(PLYWOOD_SOURCE_ROOT));
}

TEST(NonFiniteCommandSimTest, EndsTheRunWithAnErrorNamingTheTimeInBothDrives) {
  for (const std::string drive : {"contact", "planar"}) {
    SCOPED_TRACE(drive);
    ExperimentRunner runner(Config(drive));
    TurnsNaN observer(0.5);
    runner.SetObserver(&observer);
    try {
      runner.Run();
      FAIL() << "a NaN wheel command must end the run";
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("the wheel override gave a non-finite wheel speed at t=0.5 s"),
                std::string::npos)
          << what;
      EXPECT_NE(what.find("left nan, right 2"), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    // The robot drove until then: the error came at the bad command, not before.
    EXPECT_NEAR(runner.scene().time_s(), 0.5, 1e-9);
  }
}

}  // namespace
}  // namespace plywood::sim
