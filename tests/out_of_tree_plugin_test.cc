// Issue 11's acceptance for plug-ins: the out-of-tree example (examples/out_of_tree), built
// against the installed package by the fixture tests.install_and_build_example and loaded by
// `plywood run` as a plug-in, scores exactly as the same sources compiled into this test and
// registered in-process, through the same protocol code; its config.yaml re-runs it.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "eval/protocol.h"
#include "examples/out_of_tree/register_lab_algorithms.h"
#include "sim/config/experiment_config.h"
#include "sim/config/plugin_loader.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;
using testing::MakeTempDir;
using testing::RunPlywood;
using testing::Slurp;
using testing::SourceRoot;

// The number at `path` (e.g. {"lines", "lab_endpoint_fit", "recall"}) in metrics.json's nested,
// sorted, one-key-per-line layout; NaN when absent.
double MetricsNumber(const std::string& json, const std::vector<std::string>& path) {
  std::size_t at = 0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const std::string key = "\"" + path[i] + "\": " + (i + 1 < path.size() ? "{" : "");
    at = json.find(key, at);
    if (at == std::string::npos) return std::nan("");
    at += key.size();
  }
  return std::strtod(json.c_str() + at, nullptr);
}

fs::path Experiment() { return SourceRoot() / "examples/out_of_tree/experiment.yaml"; }

TEST(OutOfTreePluginTest, PluginScoresExactlyAsTheSameCodeCompiledIn) {
  const fs::path plugin = PLYWOOD_EXAMPLE_PLUGIN;
  ASSERT_TRUE(fs::exists(plugin)) << plugin << " is built by tests.install_and_build_example";
  const fs::path dir = MakeTempDir("out_of_tree_plugin");

  // As a plug-in, through the command line.
  const auto result =
      RunPlywood("run " + Experiment().string() + " --quiet --no-snapshot --out " +
                     (dir / "plugin").string() + " --set 'plugins=[" + plugin.string() + "]'",
                 dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;

  // Compiled in: the same sources, registered in this process, run by the same protocol code.
  perception::AlgorithmRegistry lab_algorithms;
  lab::RegisterLabAlgorithms(lab_algorithms);
  sim::RegisterAlgorithms(lab_algorithms);
  const sim::ExperimentConfig config = sim::LoadExperimentConfig(Experiment(), {"plugins=[]"});
  ASSERT_EQ(eval::RunProtocol({config, dir / "compiled_in", /*quiet=*/true, /*snapshots=*/false}),
            0);

  const std::string plugin_metrics = Slurp(dir / "plugin" / "metrics.json");
  const std::string compiled_metrics = Slurp(dir / "compiled_in" / "metrics.json");
  ASSERT_FALSE(plugin_metrics.empty());
  EXPECT_EQ(plugin_metrics, compiled_metrics);
  EXPECT_EQ(Slurp(dir / "plugin" / "trajectory.csv"),
            Slurp(dir / "compiled_in" / "trajectory.csv"));

  // Scored like the built-ins, under their own names: every line metric and every odometry metric.
  for (const char* key : {"recall", "precision", "sigma_r_m", "sigma_alpha_deg", "points_per_line",
                          "lines_per_scan"}) {
    EXPECT_FALSE(std::isnan(MetricsNumber(plugin_metrics, {"lines", "lab_endpoint_fit", key})))
        << key;
  }
  for (const char* key : {"final_error_m", "heading_error_deg", "drift_percent", "ate_rms_m"}) {
    EXPECT_FALSE(std::isnan(MetricsNumber(plugin_metrics, {"odometry", "lab_complementary", key})))
        << key;
  }
  EXPECT_NE(Slurp(dir / "plugin" / "trajectory.csv").find("lab_complementary_x_m"),
            std::string::npos);
  // And they do their jobs: the walls of the office are found and placed to within centimetres,
  // and the gyro blend keeps the heading far better than the encoders on a 3 % track error.
  EXPECT_GT(MetricsNumber(plugin_metrics, {"lines", "lab_endpoint_fit", "recall"}), 0.7);
  EXPECT_GT(MetricsNumber(plugin_metrics, {"lines", "lab_endpoint_fit", "precision"}), 0.8);
  // Nguyen's sigma of d_r includes short segments far from the foot of their perpendicular, whose
  // r carries the lever arm (docs/lines.md, Scoring): within the 5 cm endpoint tolerance.
  EXPECT_LT(MetricsNumber(plugin_metrics, {"lines", "lab_endpoint_fit", "sigma_r_m"}), 0.05);
  EXPECT_LT(std::abs(MetricsNumber(plugin_metrics,
                                   {"odometry", "lab_complementary", "heading_error_deg"})),
            std::abs(MetricsNumber(plugin_metrics, {"odometry", "encoder", "heading_error_deg"})));

  // config.yaml names the plug-in and its options, and re-runs to the same bytes.
  const std::string recorded = Slurp(dir / "plugin" / "config.yaml");
  EXPECT_NE(recorded.find(plugin.lexically_normal().string()), std::string::npos) << recorded;
  EXPECT_NE(recorded.find("lab_endpoint_fit:\n    min_points: 6"), std::string::npos) << recorded;
  EXPECT_NE(recorded.find("lab_complementary:\n    gyro_weight: 0.9"), std::string::npos)
      << recorded;
  const auto rerun = RunPlywood("run " + (dir / "plugin" / "config.yaml").string() +
                                    " --quiet --no-snapshot --out " + (dir / "rerun").string(),
                                dir);
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  EXPECT_EQ(Slurp(dir / "rerun" / "metrics.json"), plugin_metrics);
}

}  // namespace
}  // namespace plywood
