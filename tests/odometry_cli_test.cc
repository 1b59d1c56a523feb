// Bad odometry input on the command line: one clear line naming the file and field, exit code 2.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "plywood_paths.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;

using testing::Slurp;

const char* kExperiment =
    "name: odometry_cli\n"
    "duration_s: 1\n"
    "world: worlds/hall.xml\n"
    "sensors: {encoders: {}, gyro: {}}\n"
    "odometry: {encoder: {}, ekf: {}}\n"
    "output: {snapshot: false}\n";

void ExpectOneLineError(const std::string& name, const std::string& yaml, const std::string& args,
                        const std::vector<std::string>& must_contain) {
  const fs::path dir = testing::MakeTempDir(name);
  const fs::path file = testing::WriteFile(dir / "experiment.yaml", yaml);
  const fs::path binary = fs::path(PLYWOOD_BINARY_DIR) / "apps" / "plywood";
  const std::string command = binary.string() + " run " + file.string() + " --quiet --out " +
                              (dir / "out").string() + " " + args + " >/dev/null 2>" +
                              (dir / "stderr").string();
  const int status = std::system(command.c_str());
  const std::string err = Slurp(dir / "stderr");
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 2) << err;
  ASSERT_FALSE(err.empty());
  EXPECT_EQ(err.find('\n'), err.size() - 1) << "not one line: " << err;
  for (const std::string& text : must_contain) {
    EXPECT_NE(err.find(text), std::string::npos) << "expected '" << text << "' in: " << err;
  }
  EXPECT_FALSE(fs::exists(dir / "out" / "metrics.json"));
}

TEST(OdometryCliTest, UnknownEstimator) {
  ExpectOneLineError("UnknownEstimator", kExperiment, "--set odometry.kalman={}",
                     {"experiment.yaml", "odometry.kalman", "unknown key", "ekf"});
}

TEST(OdometryCliTest, NegativeWheelRadius) {
  ExpectOneLineError("NegativeWheelRadius", kExperiment, "--set robot.nominal.wheel_radius_m=-0.1",
                     {"experiment.yaml", "robot.nominal.wheel_radius_m"});
}

TEST(OdometryCliTest, NanGain) {
  ExpectOneLineError("NanGain", kExperiment, "--set odometry.weighted.gyro_gain=.nan",
                     {"experiment.yaml", "odometry.weighted", "gyro_gain"});
}

TEST(OdometryCliTest, GyroEstimatorWithoutGyro) {
  ExpectOneLineError("GyroEstimatorWithoutGyro", kExperiment, "--set sensors.gyro.enabled=false",
                     {"experiment.yaml", "odometry.ekf", "sensors.gyro"});
}

TEST(OdometryCliTest, BadIntegration) {
  ExpectOneLineError("BadIntegration", kExperiment, "--set odometry.encoder.integration=euler",
                     {"experiment.yaml", "odometry.encoder.integration", "midpoint or arc"});
}

}  // namespace
}  // namespace plywood
