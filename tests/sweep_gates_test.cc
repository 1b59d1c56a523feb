// CI gates on generated worlds: each runs a small seeded sweep (experiments/sweeps/ci/) through
// `plywood sweep` and fails when a group's mean metric is worse than its committed baseline
// (tests/baselines/sweep_*.json) by more than the baseline's margin. The worlds are drawn by the
// world generator with their own seed, so no algorithm was tuned on them.

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "eval/sweep/sweep_csv.h"
#include "tests/support/cli_test_support.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;

void CheckGate(const std::string& baseline_name) {
  const fs::path baseline_file = testing::SourceRoot() / "tests" / "baselines" / baseline_name;
  const nlohmann::json baseline = nlohmann::json::parse(testing::Slurp(baseline_file));
  const fs::path dir = testing::MakeTempDir("SweepGate_" + baseline_name);
  const std::string sweep = (testing::SourceRoot() / baseline["sweep"].get<std::string>()).string();
  const auto r =
      testing::RunPlywood("sweep " + sweep + " --out " + (dir / "out").string() + " --quiet", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = eval::ParseCsv(testing::Slurp(dir / "out" / "summary.csv"));
  ASSERT_GE(rows.size(), 2u);
  // summary.csv: GROUP, metric, n, mean, ...
  std::map<std::pair<std::string, std::string>, double> measured;
  for (std::size_t i = 1; i < rows.size(); ++i)
    measured[{rows[i][0], rows[i][1]}] = std::stod(rows[i][3]);
  const bool higher_is_better = baseline["better"] == "higher";
  const double margin = baseline["margin"].get<double>();
  int checked = 0;
  for (const auto& [group, metrics] : baseline["values"].items()) {
    for (const auto& [metric, value] : metrics.items()) {
      SCOPED_TRACE(group + " " + metric);
      const auto it = measured.find({group, metric});
      ASSERT_NE(it, measured.end()) << "missing from summary.csv";
      const double limit =
          higher_is_better ? value.get<double>() - margin : value.get<double>() + margin;
      if (higher_is_better) {
        EXPECT_GE(it->second, limit) << "baseline " << value;
      } else {
        EXPECT_LE(it->second, limit) << "baseline " << value;
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 4);
}

TEST(SweepGatesTest, LineExtractorsOnGeneratedWorlds) {
  CheckGate("sweep_lines_generated_subset.json");
}

TEST(SweepGatesTest, SonarMapOnGeneratedRooms) {
  CheckGate("sweep_sonar_map_generated_subset.json");
}

}  // namespace
}  // namespace plywood
