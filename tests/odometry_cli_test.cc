// Bad odometry input on the command line: one clear line naming the file and field, exit code 2.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <yaml-cpp/yaml.h>

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

// audit s43: scripts/profile_args, the way a noise profile reaches `plywood run`, passed a CRLF
// line's CR on into the value ("slip_sigma: expected a finite number, got '0.003 '", the CR shown
// as a space) and a ' # comment' after a value as the arguments '#' and its words ("--set #:
// expected key.path=value"); the sweep reads such a profile. Now it reads the lines as the sweep
// does, and takes a profile file by its path too.
TEST(OdometryCliTest, AProfileWithCrlfLinesAndCommentsReachesTheRunAsTheSweepReadsIt) {
  const fs::path dir = testing::MakeTempDir("ProfileArgs");
  const fs::path experiment = testing::WriteFile(dir / "experiment.yaml", kExperiment);
  const fs::path profile = testing::WriteFile(
      dir / "worn.set",
      "\xEF\xBB\xBF# a worn drive\r\nsensors.encoders.slip_sigma=0.003 # worn tyres\r\n\r\n"
      "odometry.encoder.gain=1.01  \r\n");
  const fs::path script = testing::SourceRoot() / "scripts" / "profile_args";
  const testing::CliResult result = testing::RunPlywood(
      "run " + experiment.string() + " --quiet --out " + (dir / "out").string() + " $(" +
          script.string() + " " + profile.string() + ")",
      dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const YAML::Node config = YAML::LoadFile((dir / "out" / "config.yaml").string());
  EXPECT_EQ(config["sensors"]["encoders"]["slip_sigma"].as<double>(), 0.003);
  EXPECT_EQ(config["odometry"]["encoder"]["gain"].as<double>(), 1.01);
}

}  // namespace
}  // namespace plywood
