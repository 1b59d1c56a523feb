// CI gate for odometry: seed 004's short circuit with the realistic profile and a fixed seed; fails
// when any estimator's drift grows beyond the committed baseline (tests/baselines/odometry.json)
// plus its margin, and prints every figure.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <string>

#include "plywood_paths.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"

namespace plywood {
namespace {

TEST(OdometryBaselineTest, DriftDoesNotWorsen) {
  const std::string root = PLYWOOD_SOURCE_ROOT;
  const YAML::Node baseline = YAML::LoadFile(root + "/tests/baselines/odometry.json");
  const double margin = baseline["margin_percent"].as<double>();
  const sim::ExperimentConfig config =
      sim::LoadExperimentConfig(root + "/" + baseline["experiment"].as<std::string>(),
                                {"output.snapshot=false", "output.sensor_logs=false", "seed=1"});
  sim::ExperimentRunner runner(config);
  runner.Run();
  const sim::Metrics& m = runner.record().metrics;
  EXPECT_EQ(m.Number("sensors.bumpers.contact_samples"), 0.0);
  for (const auto& entry : baseline["drift_percent"]) {
    const std::string name = entry.first.as<std::string>();
    const double allowed = entry.second.as<double>() + margin;
    const double drift = m.Number("odometry." + name + ".drift_percent");
    std::printf("%-10s drift %.3f %% (baseline %.2f %%, allowed %.2f %%), ATE %.4f m\n",
                name.c_str(), drift, entry.second.as<double>(), allowed,
                m.Number("odometry." + name + ".ate_rms_m"));
    EXPECT_LE(drift, allowed) << name;
  }
}

}  // namespace
}  // namespace plywood
