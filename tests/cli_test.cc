// End-to-end tests of the `plywood` command line: bad input gives one clear line and exit code 2,
// and a run is reproducible from its config and seed, byte for byte.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;
using testing::MakeTempDir;
using testing::SourceRoot;
using testing::WriteFile;

using Result = testing::CliResult;
using testing::RunPlywood;
using testing::Slurp;

// A short noisy experiment in a small room; every sensor on, so every log is exercised.
std::string SmallExperiment() {
  return "name: small\n"
         "seed: 5\n"
         "duration_s: 3\n"
         "world: worlds/seed000_room_1.xml\n"
         "robot: {model: p3dx, spawn: {x_m: 0, y_m: 0, theta_deg: 0}}\n"
         "controller: {type: wheel_script, segments: [[1.5, 3, 3], [1.5, -2, 2]]}\n"
         "sensors:\n"
         "  laser: {range_noise_sigma_m: 0.01, dropout_probability: 0.01}\n"
         "  sonar: {rate_hz: 10}\n"
         "  encoders: {slip_sigma: 0.02}\n"
         "  gyro: {bias_random_walk_rad_s_per_sqrt_s: 0.001}\n"
         "  bumpers: {}\n"
         "output: {snapshot: false}\n";
}

class BadInputTest : public ::testing::Test {
 protected:
  // Writes `yaml` into experiments-like folder, runs it and checks the one-line error.
  void ExpectOneLineError(const std::string& yaml, const std::string& extra_args,
                          const std::vector<std::string>& must_contain) {
    const fs::path dir =
        MakeTempDir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    const fs::path file = WriteFile(dir / "experiment.yaml", yaml);
    const Result result = RunPlywood(
        "run " + file.string() + " --quiet --out " + (dir / "out").string() + " " + extra_args,
        dir);
    EXPECT_EQ(result.exit_code, 2) << result.err;
    ASSERT_FALSE(result.err.empty());
    EXPECT_EQ(result.err.find('\n'), result.err.size() - 1) << "not one line: " << result.err;
    EXPECT_EQ(result.err.rfind("plywood: ", 0), 0u) << result.err;
    for (const std::string& text : must_contain) {
      EXPECT_NE(result.err.find(text), std::string::npos)
          << "expected '" << text << "' in: " << result.err;
    }
    EXPECT_FALSE(fs::exists(dir / "out" / "metrics.json")) << "a bad run must not write results";
  }

  static std::string Replace(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  }
};

TEST_F(BadInputTest, BrokenYamlSyntax) {
  ExpectOneLineError("name: [unclosed\nseed: 1\n", "", {"experiment.yaml", "not valid YAML"});
}

TEST_F(BadInputTest, UnknownKey) {
  ExpectOneLineError(SmallExperiment() + "colour: red\n", "",
                     {"experiment.yaml", "colour", "unknown key"});
}

TEST_F(BadInputTest, UnknownNestedKeyNamesItsPath) {
  ExpectOneLineError(
      Replace(SmallExperiment(), "sonar: {rate_hz: 10}", "sonar: {rate_hz: 10, bogus: 1}"), "",
      {"experiment.yaml", "sensors.sonar.bogus", "unknown key"});
}

// s42b: a null or empty key was "plywood: experiment.yaml: unknown key (known here: ...)",
// naming no field; it is named as YAML writes a null, or as "".
TEST_F(BadInputTest, ANullOrEmptyKeyIsNamed) {
  ExpectOneLineError(SmallExperiment() + "~: 5\n", "",
                     {"experiment.yaml: ~: unknown key: a key that is null or empty"});
  ExpectOneLineError(
      Replace(SmallExperiment(), "sonar: {rate_hz: 10}", "sonar: {rate_hz: 10, null: 1}"), "",
      {"experiment.yaml: sensors.sonar.~: unknown key"});
  ExpectOneLineError(SmallExperiment() + "\"\": 5\n", "",
                     {"experiment.yaml: \"\": unknown key: a key that is null or empty"});
}

TEST_F(BadInputTest, WrongType) {
  ExpectOneLineError(Replace(SmallExperiment(), "duration_s: 3", "duration_s: three"), "",
                     {"experiment.yaml", "duration_s", "number"});
}

TEST_F(BadInputTest, UnknownDrive) {
  ExpectOneLineError(
      SmallExperiment() + "physics: {drive: kinematic}\n", "",
      {"experiment.yaml", "physics.drive", "expected contact or planar", "'kinematic'"});
}

TEST_F(BadInputTest, DriveOfTheWrongType) {
  ExpectOneLineError(SmallExperiment() + "physics: {drive: [planar]}\n", "",
                     {"experiment.yaml", "physics.drive", "expected a string, got a list"});
}

TEST_F(BadInputTest, MissingWorldFile) {
  ExpectOneLineError(Replace(SmallExperiment(), "worlds/seed000_room_1.xml", "worlds/nowhere.xml"),
                     "", {"experiment.yaml", "world", "no such file", "nowhere.xml"});
}

TEST_F(BadInputTest, WorldThatDoesNotCompile) {
  const fs::path dir = MakeTempDir("BrokenWorldFile");
  const fs::path world =
      WriteFile(dir / "broken_room.xml",
                "<mujoco><worldbody><geom type=\"box\" size=\"1 1\"/></worldbody>"
                "</mujoco>\n");
  ExpectOneLineError(Replace(SmallExperiment(), "worlds/seed000_room_1.xml", world.string()), "",
                     {"broken_room.xml", "does not compile"});
}

TEST_F(BadInputTest, NanValue) {
  ExpectOneLineError(
      Replace(SmallExperiment(), "range_noise_sigma_m: 0.01", "range_noise_sigma_m: .nan"), "",
      {"experiment.yaml", "sensors.laser.range_noise_sigma_m", "finite"});
}

TEST_F(BadInputTest, NegativeValue) {
  ExpectOneLineError(
      Replace(SmallExperiment(), "range_noise_sigma_m: 0.01", "range_noise_sigma_m: -0.01"), "",
      {"experiment.yaml", "sensors.laser.range_noise_sigma_m"});
}

TEST_F(BadInputTest, NegativeWheelRadius) {
  ExpectOneLineError(SmallExperiment(), "--set robot.nominal.wheel_radius_m=-0.1",
                     {"experiment.yaml", "robot.nominal.wheel_radius_m", "> 0"});
}

TEST_F(BadInputTest, UnknownRobot) {
  ExpectOneLineError(Replace(SmallExperiment(), "model: p3dx", "model: roomba"), "",
                     {"experiment.yaml", "robot.model", "unknown robot 'roomba'"});
}

TEST_F(BadInputTest, UnknownSensor) {
  ExpectOneLineError(SmallExperiment(), "--set sensors.radar.rate_hz=5",
                     {"experiment.yaml", "sensors.radar", "unknown key"});
}

TEST_F(BadInputTest, SensorTheRobotCannotCarry) {
  ExpectOneLineError(Replace(SmallExperiment(), "model: p3dx", "model: magellan_pro"), "",
                     {"experiment.yaml", "sensors.laser", "magellan_pro"});
}

TEST_F(BadInputTest, UnknownController) {
  ExpectOneLineError(SmallExperiment(), "--set controller.type=teleport",
                     {"experiment.yaml", "controller.type", "teleport"});
}

TEST_F(BadInputTest, MalformedOverride) {
  ExpectOneLineError(SmallExperiment(), "--set seed", {"--set seed", "key.path=value"});
}

TEST_F(BadInputTest, ControllerOptionOutOfRange) {
  ExpectOneLineError(SmallExperiment(), "--set controller.segments=[[-1,1,1]]",
                     {"experiment.yaml", "controller", "duration_s"});
}

TEST_F(BadInputTest, CorruptedOrMissingSonarWeights) {
  const std::string explorer = Replace(
      SmallExperiment(), "controller: {type: wheel_script, segments: [[1.5, 3, 3], [1.5, -2, 2]]}",
      "controller: {type: sonar_explorer, weights_file: weights.txt}");
  const fs::path dir = MakeTempDir("sonar_weights_fixture");
  // Truncated mid-layer, a word where a number goes, and no file at all: each one line, exit 2.
  const std::string good = Slurp(SourceRoot() / "models" / "sonar_net_v1.txt");
  ASSERT_GT(good.size(), 400u);
  const fs::path truncated = WriteFile(dir / "truncated.txt", good.substr(0, 300));
  const fs::path garbled =
      WriteFile(dir / "garbled.txt", Replace(good, "layer 16 5", "layer sixteen 5"));
  for (const auto& [path, words] : std::vector<std::pair<fs::path, std::vector<std::string>>>{
           {truncated, {"truncated.txt", "line "}},
           {garbled, {"garbled.txt", "line "}},
           {dir / "absent.txt", {"absent.txt", "cannot open"}},
           // A device was read forever (fuzz30).
           {"/dev/zero", {"/dev/zero", "not a regular file"}}}) {
    SCOPED_TRACE(path.string());
    std::vector<std::string> must = {"experiment.yaml", "controller", "weights_file"};
    must.insert(must.end(), words.begin(), words.end());
    ExpectOneLineError(explorer, "--set controller.weights_file=" + path.string(), must);
  }
}

TEST(CliTest, MissingExperimentFile) {
  const fs::path dir = MakeTempDir("MissingExperimentFile");
  const Result result = RunPlywood("run /nonexistent/experiment.yaml", dir);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("/nonexistent/experiment.yaml"), std::string::npos) << result.err;
}

TEST(CliTest, UnknownCommandAndOption) {
  const fs::path dir = MakeTempDir("UnknownCommand");
  EXPECT_EQ(RunPlywood("fly", dir).exit_code, 2);
  EXPECT_EQ(RunPlywood("run x.yaml --colour red", dir).exit_code, 2);
}

class ReproducibilityTest : public ::testing::Test {
 protected:
  static fs::path Run(const std::string& name, const std::string& extra_args) {
    const fs::path dir = MakeTempDir("Reproducibility_" + name);
    const fs::path file = WriteFile(dir / "small.yaml", SmallExperiment());
    const Result result = RunPlywood(
        "run " + file.string() + " --quiet --out " + (dir / "out").string() + " " + extra_args,
        dir);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return dir / "out";
  }
};

TEST_F(ReproducibilityTest, SameSeedSameBytesDifferentSeedDifferentNumbers) {
  const fs::path a = Run("a", "--seed 11");
  const fs::path b = Run("b", "--seed 11");
  const fs::path c = Run("c", "--seed 12");
  for (const char* file : {"config.yaml", "trajectory.csv", "metrics.json", "laser.log",
                           "sonar.csv", "encoders.csv", "gyro.csv"}) {
    ASSERT_TRUE(fs::exists(a / file)) << file;
    EXPECT_EQ(Slurp(a / file), Slurp(b / file)) << file << " differs between equal seeds";
  }
  for (const char* file : {"trajectory.csv", "metrics.json", "laser.log", "encoders.csv"}) {
    EXPECT_NE(Slurp(a / file), Slurp(c / file)) << file << " is the same for different seeds";
  }
}

TEST_F(ReproducibilityTest, ResolvedConfigReproducesTheRun) {
  const fs::path first = Run("first", "");
  const fs::path dir = MakeTempDir("Reproducibility_again");
  const Result again = RunPlywood(
      "run " + (first / "config.yaml").string() + " --quiet --out " + (dir / "out").string(), dir);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(Slurp(first / "config.yaml"), Slurp(dir / "out" / "config.yaml"));
  EXPECT_EQ(Slurp(first / "trajectory.csv"), Slurp(dir / "out" / "trajectory.csv"));
  EXPECT_EQ(Slurp(first / "metrics.json"), Slurp(dir / "out" / "metrics.json"));
}

TEST(CliTest, UserWorldOutsideTheRepoRunsAndWritesEveryOutput) {
  const fs::path dir = MakeTempDir("UserWorld");
  // A 4 x 3 m room of the user's own, rotated 10 degrees, written by hand.
  const fs::path world =
      WriteFile(dir / "my_rooms" / "my_room.xml",
                "<mujoco model=\"my_room\"><worldbody>\n"
                "  <geom name=\"floor\" type=\"plane\" size=\"5 5 0.1\"/>\n"
                "  <body euler=\"0 0 10\">\n"
                "    <geom type=\"box\" pos=\"2 0 0.5\" size=\"0.009 1.5 0.5\"/>\n"
                "    <geom type=\"box\" pos=\"-2 0 0.5\" size=\"0.009 1.5 0.5\"/>\n"
                "    <geom type=\"box\" pos=\"0 1.5 0.5\" size=\"2 0.009 0.5\"/>\n"
                "    <geom type=\"box\" pos=\"0 -1.5 0.5\" size=\"2 0.009 0.5\"/>\n"
                "  </body>\n"
                "</worldbody></mujoco>\n");
  const fs::path experiment = WriteFile(dir / "small.yaml", SmallExperiment());
  const Result result =
      RunPlywood("run " + experiment.string() + " --out " + (dir / "out").string() +
                     " --set world=" + world.string() + " --set output.snapshot=true",
                 dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* file : {"config.yaml", "trajectory.csv", "metrics.json", "laser.log",
                           "walls.csv", "snapshot.png"}) {
    EXPECT_TRUE(fs::exists(dir / "out" / file)) << file;
  }
  EXPECT_NE(result.out.find("results"), std::string::npos) << result.out;
  // 4 boxes -> 16 ground-truth faces.
  const std::string walls = Slurp(dir / "out" / "walls.csv");
  EXPECT_EQ(std::count(walls.begin(), walls.end(), '\n'), 17) << walls;
}

// The laser's sigma_m alias inside a whole mapping given by --set reads as in a file (was refused
// as `sensors.laser.sigma_m: unknown key`: aliases were normalised in the file and in each --set's
// key, not in its value). Given beside its long name, the --set is named.
TEST(CliTest, ALaserMappingGivenBySetReadsTheSigmaAliasAsAFileDoes) {
  const fs::path dir = MakeTempDir("LaserMappingAlias");
  const fs::path experiment = WriteFile(dir / "small.yaml", SmallExperiment());
  const Result result =
      RunPlywood("run " + experiment.string() + " --quiet --out " + (dir / "out").string() +
                     " --set duration_s=0.5 --set 'sensors.laser={sigma_m: 0.02}'",
                 dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string config = Slurp(dir / "out" / "config.yaml");
  EXPECT_NE(config.find("range_noise_sigma_m: 0.02"), std::string::npos) << config;
  EXPECT_EQ(config.find("sigma_m: 0.01"), std::string::npos) << config;

  const Result both =
      RunPlywood("run " + experiment.string() + " --quiet --out " + (dir / "both").string() +
                     " --set 'sensors.laser={sigma_m: 0.02, range_noise_sigma_m: 0.03}'",
                 dir);
  EXPECT_EQ(both.exit_code, 2) << both.err;
  EXPECT_NE(both.err.find("--set sensors.laser={sigma_m: 0.02, range_noise_sigma_m: 0.03}: "
                          "sensors.laser.sigma_m: give either sigma_m or range_noise_sigma_m"),
            std::string::npos)
      << both.err;
  EXPECT_FALSE(fs::exists(dir / "both"));
}
}  // namespace
}  // namespace plywood
