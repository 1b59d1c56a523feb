// Registered algorithms in-process: RegisterAlgorithms keeps names unambiguous, and a registered
// controller, estimator and extractor are read from YAML, checked, written back to config.yaml and
// run exactly like built-in ones.

#include "sim/config/plugin_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "plywood_paths.h"
#include "sim/config/config_error.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"

namespace plywood::sim {
namespace {

using robot::ParameterMap;

// Drives straight at speed_m_s (both wheels alike): the whole controller.
class StraightController final : public robot::Controller {
 public:
  StraightController(const robot::DiffDriveSpec& nominal, double speed_m_s)
      : wheel_rad_s_(speed_m_s / nominal.wheel_radius_m) {}
  msgs::WheelSpeedCommand Update(const robot::ControllerInput&) override {
    return {wheel_rad_s_, wheel_rad_s_};
  }
  bool Finished() const override { return false; }

 private:
  double wheel_rad_s_;
};

// Stands still whatever it is fed: the estimate stays at the initial pose.
class FrozenOdometry final : public robot::OdometryEstimator {
 public:
  explicit FrozenOdometry(const msgs::Pose2D& X_WR) : X_WR_(X_WR) {}
  void AddEncoders(const msgs::WheelEncoders&) override {}
  msgs::Pose2D pose() const override { return X_WR_; }

 private:
  msgs::Pose2D X_WR_;
};

// Finds nothing.
class BlindExtractor final : public perception::LineExtractor {
 public:
  std::string name() const override { return "test_blind"; }
  std::vector<perception::LineSegment> Extract(const perception::ScanPoints&) const override {
    return {};
  }
};

perception::AlgorithmRegistry TestAlgorithms() {
  perception::AlgorithmRegistry r;
  r.controllers.Add(
      {"test_straight", [](const robot::DiffDriveSpec& nominal, const ParameterMap& o) {
         return std::make_unique<StraightController>(nominal,
                                                     o.GetDouble("speed_m_s", 0.2, 0.0, 1.0));
       }});
  r.odometry_estimators.Add(
      {"test_frozen", /*needs_gyro=*/true,
       [](const robot::OdometryGeometry&, const msgs::Pose2D& X_WR, const ParameterMap&) {
         return std::make_unique<FrozenOdometry>(X_WR);
       }});
  r.line_extractors.Add(
      {"test_blind", [](const ParameterMap&) { return std::make_unique<BlindExtractor>(); }});
  return r;
}

// Registered once for the whole test program (names cannot be registered twice).
class RegisteredAlgorithmsTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { RegisterAlgorithms(TestAlgorithms()); }

  static ExperimentConfig Parse(const std::string& yaml) {
    return ParseExperimentConfig(yaml, "inline.yaml", std::filesystem::path(PLYWOOD_SOURCE_ROOT));
  }
  static std::string ErrorOf(const std::string& yaml) {
    try {
      Parse(yaml);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "";
  }
};

constexpr const char* kExperiment =
    "duration_s: 5\n"
    "world: worlds/hall.xml\n"
    "robot: {spawn: {x_m: 0, y_m: 0, theta_deg: 0}}\n"
    "controller: {type: test_straight, speed_m_s: 0.3, steer_by: test_frozen}\n"
    "sensors: {laser: {}, encoders: {}, gyro: {}}\n"
    "odometry: {encoder: {}, test_frozen: {}}\n"
    "lines: {extractors: [test_blind, split_and_merge]}\n"
    "output: {snapshot: false}\n";

TEST_F(RegisteredAlgorithmsTest, NamesMustNotShadowBuiltInsSectionKeysOrEachOther) {
  const auto rejects = [](const perception::AlgorithmRegistry& r, const std::string& text) {
    try {
      RegisterAlgorithms(r);
      ADD_FAILURE() << "accepted, expected: " << text;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  const auto extractor = [](const ParameterMap&) { return std::make_unique<BlindExtractor>(); };
  const auto estimator = [](const robot::OdometryGeometry&, const msgs::Pose2D& X,
                            const ParameterMap&) { return std::make_unique<FrozenOdometry>(X); };
  // audit s33: "scans" (metrics.json's lines.scans) and "truth" (trajectory.truth.tum, whose
  // truth_* columns an estimator "truth" would have written twice) were accepted.
  for (const char* name : {"ransac", "scoring", "extractors", "scans", "test_blind"}) {
    perception::AlgorithmRegistry r;
    r.line_extractors.Add({name, extractor});
    rejects(r, std::string("line extractor '") + name + "'");
  }
  // audit39: "ground_truth", controller.steer_by's name for the truth and its default, was
  // accepted, and the controller then steered by that estimator in every run that enabled it.
  for (const char* name : {"ekf", "calibration", "truth", "ground_truth", "test_frozen"}) {
    perception::AlgorithmRegistry r;
    r.odometry_estimators.Add({name, false, estimator});
    rejects(r, std::string("odometry estimator '") + name + "'");
  }
  perception::AlgorithmRegistry r;
  r.controllers.Add({"waypoints", [](const robot::DiffDriveSpec& n, const ParameterMap&) {
                       return std::make_unique<StraightController>(n, 0.1);
                     }});
  r.line_extractors.Add({"test_fine", extractor});
  rejects(r, "controller 'waypoints'");
  // All or none: the valid extractor beside the bad controller was not registered.
  EXPECT_EQ(RegisteredAlgorithms().line_extractors.Find("test_fine"), nullptr);
}

TEST_F(RegisteredAlgorithmsTest, RunLikeBuiltInsAndReRunFromConfigYaml) {
  const ExperimentConfig config = Parse(kExperiment);
  ExperimentRunner runner(config);
  runner.Run();
  const RunRecord& record = runner.record();
  ASSERT_EQ(record.estimator_names, (std::vector<std::string>{"encoder", "test_frozen"}));
  // The registered controller drove 0.3 m/s for 5 s (wheels spin up within a few steps); the
  // registered estimator, which it steers by, never moved.
  EXPECT_NEAR(record.metrics.Number("truth.distance_m"), 1.5, 0.1);
  EXPECT_NEAR(record.metrics.Number("odometry.test_frozen.final_error_m"),
              record.metrics.Number("truth.distance_m"), 0.05);
  EXPECT_LT(record.metrics.Number("odometry.encoder.final_error_m"), 0.05);

  const std::string yaml = ExperimentConfigToYaml(config);
  EXPECT_NE(yaml.find("type: test_straight"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("speed_m_s: 0.3"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("test_frozen: {}"), std::string::npos) << yaml;
  EXPECT_EQ(ExperimentConfigToYaml(Parse(yaml)), yaml);
}

TEST_F(RegisteredAlgorithmsTest, BadOptionsAreReportedWhileReadingTheConfig) {
  std::string yaml = kExperiment;
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string changed = yaml;
    changed.replace(changed.find(from), from.size(), to);
    return changed;
  };
  EXPECT_EQ(ErrorOf(with("speed_m_s: 0.3", "sped_m_s: 0.3")),
            "inline.yaml: controller.sped_m_s: unknown key (known here: speed_m_s)");
  EXPECT_EQ(ErrorOf(with("speed_m_s: 0.3", "speed_m_s: 3")),
            "inline.yaml: controller.speed_m_s: expected a number in [0, 1], got '3'");
  EXPECT_EQ(ErrorOf(with("speed_m_s: 0.3", "speed_m_s: {a: 1}")),
            "inline.yaml: controller.speed_m_s: expected a number, true/false or text (a "
            "registered algorithm's options are one flat mapping)");
  EXPECT_EQ(ErrorOf(with("test_frozen: {}", "test_frozen: {gain: 1}")),
            "inline.yaml: odometry.test_frozen.gain: unknown key (this algorithm takes no "
            "options)");
  EXPECT_EQ(ErrorOf(with("extractors: [test_blind, split_and_merge]}",
                         "extractors: [test_blind], test_blind: {x: 1}}")),
            "inline.yaml: lines.test_blind.x: unknown key (this algorithm takes no options)");
}

TEST_F(RegisteredAlgorithmsTest, AnEstimatorThatNeedsTheGyroNeedsTheGyro) {
  std::string yaml = kExperiment;
  yaml.replace(yaml.find(", gyro: {}"), 10, "");
  try {
    ExperimentRunner runner(Parse(yaml));
    ADD_FAILURE() << "ran without the gyro";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(),
                 "inline.yaml: odometry.test_frozen: this estimator needs sensors.gyro to be "
                 "enabled");
  }
}

}  // namespace
}  // namespace plywood::sim
