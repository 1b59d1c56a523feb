// Closed-loop wall following through the whole simulator: the P3-DX model in MuJoCo, the sonar
// cone model (specular misses, 1 % noise) or the laser, the experiment runner and the real
// controller, judged against ground truth.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <string>

#include "plywood_paths.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/experiment_runner.h"
#include "sim/world/ground_truth_walls.h"

namespace plywood::sim {
namespace {

constexpr double kDurationS = 90.0;
constexpr double kSpeedMS = 0.3;
constexpr double kDistanceM = 0.6;
// Following means the nearest wall point lies within this angle of the robot's left normal.
constexpr double kSideWindowRad = 0.6;
// Finding the first wall (from the hall's centre, 3.4 m away) is not following it.
constexpr double kSettleS = 20.0;

struct Case {
  std::string world;
  std::string spawn;  // YAML flow mapping
  std::string sensor;
};

std::string CaseName(const testing::TestParamInfo<Case>& info) {
  return info.param.world + "_" + info.param.sensor;
}

// Nearest point of any wall face to p, or nullopt when the world has none.
struct Nearest {
  double distance_m = std::numeric_limits<double>::infinity();
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
};

Nearest NearestWall(const GroundTruthWalls& walls, const Eigen::Vector2d& p) {
  Nearest best;
  for (const WallSegment& s : walls.segments) {
    const Eigen::Vector2d ab = s.b - s.a;
    const double t = std::clamp((p - s.a).dot(ab) / std::max(ab.squaredNorm(), 1e-12), 0.0, 1.0);
    const Eigen::Vector2d q = s.a + t * ab;
    if ((p - q).norm() < best.distance_m) best = {(p - q).norm(), q};
  }
  return best;
}

class WallFollowingSimTest : public testing::TestWithParam<Case> {};

TEST_P(WallFollowingSimTest, FollowsTheLeftWallWithoutTouchingIt) {
  const Case& c = GetParam();
  const std::string sensor_yaml = c.sensor == "sonar"
                                      ? "  sonar: {rate_hz: 10}\n"
                                      : "  laser: {resolution_deg: 0.5, range_max_m: 8, "
                                        "range_noise_sigma_m: 0.01, rate_hz: 10}\n";
  const std::string yaml = "name: wall_following_" + c.world + "_" + c.sensor +
                           "\n"
                           "seed: 7\n"
                           "duration_s: " +
                           std::to_string(kDurationS) +
                           "\n"
                           "world: worlds/" +
                           c.world +
                           ".xml\n"
                           "robot: {model: p3dx, spawn: " +
                           c.spawn +
                           "}\n"
                           "controller: {type: wall_following, sensor: " +
                           c.sensor + ", side: left, distance_m: " + std::to_string(kDistanceM) +
                           ", speed_m_s: " + std::to_string(kSpeedMS) +
                           "}\n"
                           "sensors:\n" +
                           sensor_yaml + "  encoders: {}\n  bumpers: {}\n";
  const ExperimentConfig config =
      ParseExperimentConfig(yaml, "inline", std::filesystem::path(PLYWOOD_SOURCE_ROOT));
  ExperimentRunner runner(config);
  runner.Run();
  const RunRecord& record = runner.record();

  EXPECT_EQ(record.metrics.Number("sensors.bumpers.contact_samples"), 0.0);
  EXPECT_GE(record.metrics.Number("truth.distance_m"), 0.5 * kSpeedMS * kDurationS);

  // The walls at the sensor's height: the sonar ring at 0.21 m passes under table tops, the laser
  // at 0.34 m too; both see wardrobes and the plywood walls.
  GroundTruthOptions at_height;
  at_height.height_m = c.sensor == "sonar" ? 0.21 : 0.34;
  const GroundTruthWalls walls = ExtractGroundTruthWalls(runner.scene().model(), at_height);
  ASSERT_FALSE(walls.segments.empty());

  double error_sum_m = 0.0, closest_m = std::numeric_limits<double>::infinity();
  int following = 0, settled = 0;
  for (const TrajectorySample& sample : record.trajectory) {
    const Eigen::Vector2d p(sample.truth.x_m, sample.truth.y_m);
    const Nearest nearest = NearestWall(walls, p);
    closest_m = std::min(closest_m, nearest.distance_m);
    if (sample.time_s < kSettleS) continue;
    ++settled;
    const Eigen::Vector2d to_wall = nearest.point - p;
    const double bearing_rad = std::atan2(to_wall.y(), to_wall.x()) - sample.truth.theta_rad;
    const double from_left_rad =
        std::remainder(bearing_rad - std::numbers::pi / 2.0, 2.0 * std::numbers::pi);
    if (std::abs(from_left_rad) > kSideWindowRad) continue;
    ++following;
    error_sum_m += std::abs(nearest.distance_m - kDistanceM);
  }
  ASSERT_GT(settled, 0);
  // Most of the time the nearest wall is the one on the left; the rest is corners and turns.
  EXPECT_GE(following, settled / 2) << following << " of " << settled;
  ASSERT_GT(following, 0);
  const double mean_error_m = error_sum_m / following;
  EXPECT_LT(mean_error_m, 0.1);
  // The P3-DX's corners are 0.36 m from its centre of rotation; contact needs less than that.
  EXPECT_GT(closest_m, 0.36);
  std::printf(
      "%s/%s: travelled %.2f m, contacts %.0f, following %d/%d, mean |error| %.3f m, "
      "closest %.3f m\n",
      c.world.c_str(), c.sensor.c_str(), record.metrics.Number("truth.distance_m"),
      record.metrics.Number("sensors.bumpers.contact_samples"), following, settled, mean_error_m,
      closest_m);
}

INSTANTIATE_TEST_SUITE_P(
    Worlds, WallFollowingSimTest,
    testing::Values(Case{"hall", "{x_m: 0, y_m: 0, theta_deg: 0}", "sonar"},
                    Case{"hall", "{x_m: 0, y_m: 0, theta_deg: 0}", "laser"},
                    Case{"office", "{x_m: -6.5, y_m: 0, theta_deg: 0}", "sonar"},
                    Case{"office", "{x_m: -6.5, y_m: 0, theta_deg: 0}", "laser"}),
    CaseName);

}  // namespace
}  // namespace plywood::sim
