// CI gate for seed 001's cognitive map: runs the four shipped room experiments in full (about a
// second each) and fails when the partition map's e or the grid's e rises above the committed
// baseline (tests/baselines/sonar_map.json) plus its margin, when e misses issue 5's goal, or when
// a bumper was pressed. Prints every figure.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <string>

#include "tests/support/mujoco_test_support.h"
#include "tests/support/sonar_map_test_support.h"

namespace plywood {
namespace {

namespace fs = std::filesystem;
using testing::MakeTempDir;
using testing::RunSonarMap;
using testing::SonarMapScore;
using testing::SourceRoot;

TEST(SonarMapBaselineTest, MapErrorDoesNotWorsen) {
  const YAML::Node baseline =
      YAML::LoadFile((SourceRoot() / "tests" / "baselines" / "sonar_map.json").string());
  const double margin = baseline["margin"].as<double>();
  const double goal = baseline["goal"].as<double>();
  const fs::path dir = MakeTempDir("sonar_map_baseline");
  for (const auto& entry : baseline["layouts"]) {
    const std::string name = entry.first.as<std::string>();
    const SonarMapScore score = RunSonarMap(name + ".yaml", dir / name);
    ASSERT_FALSE(::testing::Test::HasFatalFailure());
    std::printf("%s e %.4f grid e %.4f contact samples %.0f\n", name.c_str(), score.error,
                score.grid_error, score.contacts);
    EXPECT_LE(score.error, entry.second["error"].as<double>() + margin) << name;
    EXPECT_LE(score.error, goal) << name;
    EXPECT_LE(score.grid_error, entry.second["grid_error"].as<double>() + margin) << name;
    EXPECT_EQ(score.contacts, 0.0) << name;
    // Exploration ends because nothing is left to visit, not on a time limit.
    EXPECT_EQ(score.end_reason, "map_complete") << name;
  }
}

}  // namespace
}  // namespace plywood
