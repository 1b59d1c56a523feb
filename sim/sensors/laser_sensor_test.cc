#include "sim/sensors/laser_sensor.h"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/config/config_error.h"
#include "sim/raycast/mujoco_ray_caster.h"
#include "sim/world/scene.h"
#include "tests/support/options_test_support.h"
#include "tests/support/sample_stats.h"
#include "tests/support/sensor_test_support.h"

namespace plywood::sim {
namespace {

using plywood::testing::ExpectInvalidField;
using plywood::testing::FloorWorld;
using plywood::testing::Rectangle;
using plywood::testing::RobotIn;
using plywood::testing::RoomRange;
using plywood::testing::RoomWorld;
using plywood::testing::SampleStats;
using plywood::testing::SegmentCaster;
using plywood::testing::ToWorld;

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

TEST(LaserOptionsTest, DefaultsAreTheLms200In8mModeAtHalfDegree) {
  const LaserOptions options;
  EXPECT_NO_THROW(options.Validate());
  EXPECT_EQ(options.BeamCount(), 361);
  EXPECT_DOUBLE_EQ(options.RangeResolutionM(), 0.001);
  LaserOptions cm_mode;
  cm_mode.range_max_m = 80.0;
  EXPECT_DOUBLE_EQ(cm_mode.RangeResolutionM(), 0.01);
}

TEST(LaserOptionsTest, ValidateNamesTheField) {
  ExpectInvalidField(LaserOptions{.fov_deg = 190.0}, "fov_deg");
  ExpectInvalidField(LaserOptions{.fov_deg = 180.25}, "fov_deg");
  ExpectInvalidField(LaserOptions{.resolution_deg = 0.3}, "resolution_deg");
  ExpectInvalidField(LaserOptions{.range_max_m = 10.0}, "range_max_m");
  ExpectInvalidField(LaserOptions{.range_min_m = -0.1}, "range_min_m");
  ExpectInvalidField(LaserOptions{.range_noise_sigma_m = -0.01}, "range_noise_sigma_m");
  ExpectInvalidField(LaserOptions{.dropout_probability = 1.5}, "dropout_probability");
  ExpectInvalidField(LaserOptions{.mixed_pixel_min_jump_m = 0.0}, "mixed_pixel_min_jump_m");
  ExpectInvalidField(LaserOptions{.mixed_pixel_probability = -0.5}, "mixed_pixel_probability");
  ExpectInvalidField(LaserOptions{.rate_hz = 100.0}, "rate_hz");
}

TEST(LaserSensorTest, MissingSiteIsAConfigErrorNamingTheSite) {
  const Scene scene(RobotIn("magellan_pro", FloorWorld("laser_missing_site"), {}));  // no laser
  try {
    LaserSensor laser(scene, "laser", LaserOptions{}, 1);
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("laser"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("robot"), std::string::npos) << e.what();
  }
}

// A wall 3 m ahead of the sensor, square to its axis, wider than any beam that reaches it.
class LaserWallTest : public ::testing::Test {
 protected:
  LaserWallTest()
      : scene_(RobotIn("p3dx", FloorWorld("laser_wall"), {1.0, -0.5, 30.0 * kDeg})),
        X_WS_(scene_.SitePoseInWorld(*scene_.FindSite("laser"))),
        caster_({{ToWorld(X_WS_, kWallM, -6.0), ToWorld(X_WS_, kWallM, 6.0), 7}}) {}

  // Beam angles whose wall hit is within the 8 m range.
  static double TrueRange(double angle_rad) { return kWallM / std::cos(angle_rad); }

  static constexpr double kWallM = 3.0;
  Scene scene_;
  Eigen::Isometry3d X_WS_;
  SegmentCaster caster_;
};

TEST_F(LaserWallTest, NoiseFreeScanIsTheGeometryWithGeomIds) {
  LaserOptions options;
  options.noise_free = true;
  LaserSensor laser(scene_, "laser", options, 1);
  const ScanMeasurement m = laser.Measure(scene_, caster_);
  ASSERT_EQ(m.scan.ranges_m.size(), 361u);
  ASSERT_EQ(m.hit_geom_ids.size(), 361u);
  EXPECT_DOUBLE_EQ(m.scan.angle_min_rad, -kPi / 2.0);
  EXPECT_DOUBLE_EQ(m.scan.angle_increment_rad, 0.5 * kDeg);
  EXPECT_DOUBLE_EQ(m.scan.range_max_m, 8.0);
  EXPECT_EQ(m.scan.time_s, scene_.time_s());
  EXPECT_NEAR(m.scan.X_RS.x_m, 0.021, 1e-12);
  int hits = 0;
  for (std::size_t i = 0; i < 361; ++i) {
    const double a = m.scan.BeamAngleRad(i);
    const double expected = TrueRange(a);
    if (std::abs(a) < kPi / 2.0 && expected < 8.0 && kWallM * std::tan(std::abs(a)) < 6.0) {
      ++hits;
      EXPECT_NEAR(m.scan.ranges_m[i], expected, 1e-9) << "beam " << i;
      EXPECT_EQ(m.hit_geom_ids[i], 7);
      EXPECT_TRUE(m.scan.IsReturn(i));
    } else {
      EXPECT_EQ(m.scan.ranges_m[i], 8.0) << "beam " << i;
      EXPECT_EQ(m.hit_geom_ids[i], -1);
      EXPECT_FALSE(m.scan.IsReturn(i));
    }
  }
  EXPECT_EQ(hits, 2 * 126 + 1);  // the 12 m wall spans |a| < atan(6 / 3) = 63.4 deg
}

TEST_F(LaserWallTest, RangeNoiseIsZeroMeanWithConfiguredSigma) {
  LaserOptions options;  // sigma 10 mm, 1 mm quantisation
  LaserOptions exact = options;
  exact.noise_free = true;
  LaserSensor noisy(scene_, "laser", options, 42);
  LaserSensor clean(scene_, "laser", exact, 1);
  const ScanMeasurement truth = clean.Measure(scene_, caster_);
  SampleStats stats;
  while (stats.count() < 20000) {
    const ScanMeasurement m = noisy.Measure(scene_, caster_);
    for (std::size_t i = 0; i < m.scan.ranges_m.size(); ++i) {
      if (truth.scan.ranges_m[i] > 7.5) continue;  // keep clear of the range_max clamp
      const double e = m.scan.ranges_m[i] - truth.scan.ranges_m[i];
      stats.Add(e);
    }
  }
  const double mean = stats.Mean(), sigma = stats.Sigma();
  EXPECT_LT(std::abs(mean), 0.05 * 0.01);
  EXPECT_NEAR(sigma, 0.01, 0.05 * 0.01);
}

TEST_F(LaserWallTest, RangesAreQuantisedToTheModesUnit) {
  for (const double range_max_m : {8.0, 80.0}) {
    LaserOptions options;
    options.range_noise_sigma_m = 0.0;
    options.range_max_m = range_max_m;
    LaserSensor laser(scene_, "laser", options, 3);
    const ScanMeasurement m = laser.Measure(scene_, caster_);
    const double unit_m = options.RangeResolutionM();
    for (std::size_t i = 0; i < m.scan.ranges_m.size(); ++i) {
      if (m.hit_geom_ids[i] < 0) continue;
      const double r = m.scan.ranges_m[i];
      EXPECT_NEAR(r / unit_m, std::round(r / unit_m), 1e-6) << r;
      EXPECT_LE(std::abs(r - TrueRange(m.scan.BeamAngleRad(i))), unit_m / 2.0 + 1e-12);
    }
  }
}

TEST_F(LaserWallTest, DropoutRateMatchesAndDropoutsReportRangeMax) {
  LaserOptions options;
  options.range_noise_sigma_m = 0.0;
  options.dropout_probability = 0.05;
  LaserSensor laser(scene_, "laser", options, 7);
  int beams = 0, dropouts = 0;
  for (int scan = 0; scan < 100; ++scan) {
    const ScanMeasurement m = laser.Measure(scene_, caster_);
    for (std::size_t i = 0; i < m.scan.ranges_m.size(); ++i) {
      const double a = m.scan.BeamAngleRad(i);
      if (std::abs(a) >= kPi / 2.0 || TrueRange(a) >= 7.99 ||
          kWallM * std::tan(std::abs(a)) >= 6.0) {
        continue;
      }
      ++beams;
      if (m.scan.ranges_m[i] == 8.0) {
        ++dropouts;
        EXPECT_EQ(m.hit_geom_ids[i], -1);
      } else {
        EXPECT_EQ(m.hit_geom_ids[i], 7);
      }
    }
  }
  // 26,900 beams: the standard error of the rate is 0.0013.
  EXPECT_NEAR(static_cast<double>(dropouts) / beams, 0.05, 0.006);
}

TEST(LaserSensorTest, MixedPixelsFallBetweenTheTwoSurfacesAtDepthEdges) {
  Scene scene(RobotIn("p3dx", FloorWorld("laser_mixed"), {}));
  const Eigen::Isometry3d X_WS = scene.SitePoseInWorld(*scene.FindSite("laser"));
  // A far wall at 4 m and a near panel at 2 m covering beam angles of about -20..+20 deg.
  const SegmentCaster caster({{ToWorld(X_WS, 4.0, -5.0), ToWorld(X_WS, 4.0, 5.0), 1},
                              {ToWorld(X_WS, 2.0, -0.73), ToWorld(X_WS, 2.0, 0.73), 2}});
  LaserOptions options;
  options.range_noise_sigma_m = 0.0;
  options.mixed_pixels = true;
  options.mixed_pixel_probability = 1.0;
  LaserOptions exact = options;
  exact.noise_free = true;
  LaserSensor laser(scene, "laser", options, 11);
  const ScanMeasurement truth = LaserSensor(scene, "laser", exact, 1).Measure(scene, caster);
  for (int trial = 0; trial < 20; ++trial) {
    const ScanMeasurement m = laser.Measure(scene, caster);
    std::vector<std::size_t> mixed;
    for (std::size_t i = 0; i < m.scan.ranges_m.size(); ++i) {
      if (std::abs(m.scan.ranges_m[i] - truth.scan.ranges_m[i]) > 0.0005 + 1e-12) {
        mixed.push_back(i);
        EXPECT_GT(m.scan.ranges_m[i], 2.0 / std::cos(20.0 * kDeg) - 0.001);
        EXPECT_LT(m.scan.ranges_m[i], 4.0 / std::cos(20.0 * kDeg) + 0.001);
        EXPECT_EQ(m.hit_geom_ids[i], -1);
        // The mixed beam is a far-wall beam next to a panel beam.
        EXPECT_EQ(truth.hit_geom_ids[i], 1);
        EXPECT_TRUE(truth.hit_geom_ids[i - 1] == 2 || truth.hit_geom_ids[i + 1] == 2);
      }
    }
    // One edge on each side of the panel; a mixed value equal to the truth is a measure-zero event.
    EXPECT_EQ(mixed.size(), 2u);
  }
}

TEST(LaserSensorTest, AWallSeenAtAGrazingAngleGivesNoMixedPixels) {
  Scene scene(RobotIn("p3dx", FloorWorld("laser_grazing"), {}));
  const Eigen::Isometry3d X_WS = scene.SitePoseInWorld(*scene.FindSite("laser"));
  // A wall 0.5 m to the left running along the beam directions: past about 3 m, neighbouring
  // beams' ranges differ by more than the 0.1 m jump, yet there is no depth edge.
  const SegmentCaster caster({{ToWorld(X_WS, -1.0, 0.5), ToWorld(X_WS, 7.5, 0.5), 1}});
  LaserOptions options;
  options.range_noise_sigma_m = 0.0;
  options.mixed_pixels = true;
  options.mixed_pixel_probability = 1.0;
  LaserOptions exact = options;
  exact.noise_free = true;
  const ScanMeasurement truth = LaserSensor(scene, "laser", exact, 1).Measure(scene, caster);
  int jumps = 0;
  for (std::size_t i = 0; i + 1 < truth.scan.ranges_m.size(); ++i) {
    const double a = truth.scan.ranges_m[i], b = truth.scan.ranges_m[i + 1];
    if (a < options.range_max_m && b < options.range_max_m && std::abs(a - b) > 0.1) ++jumps;
  }
  ASSERT_GE(jumps, 5);  // the old rule would have mixed these
  const ScanMeasurement m = LaserSensor(scene, "laser", options, 11).Measure(scene, caster);
  for (std::size_t i = 0; i < m.scan.ranges_m.size(); ++i) {
    EXPECT_NEAR(m.scan.ranges_m[i], truth.scan.ranges_m[i], 0.0005 + 1e-12) << "beam " << i;
  }
}

TEST(LaserSensorTest, SameSeedSameScanOtherSeedOtherScan) {
  Scene scene(RobotIn("p3dx", FloorWorld("laser_seed"), {}));
  const Eigen::Isometry3d X_WS = scene.SitePoseInWorld(*scene.FindSite("laser"));
  const SegmentCaster caster({{ToWorld(X_WS, 2.0, -5.0), ToWorld(X_WS, 2.0, 5.0), 1}});
  LaserSensor a(scene, "laser", LaserOptions{}, 5), b(scene, "laser", LaserOptions{}, 5),
      c(scene, "laser", LaserOptions{}, 6);
  const auto ra = a.Measure(scene, caster).scan.ranges_m;
  EXPECT_EQ(ra, b.Measure(scene, caster).scan.ranges_m);
  EXPECT_NE(ra, c.Measure(scene, caster).scan.ranges_m);
}

// Without dropouts a returned beam still takes its dropout draw (the engine skips it): the noise
// that follows is what a sensor whose dropout can never happen (it needs a draw of exactly 0)
// gets, scan after scan. A beam that skipped the draw would shift every later beam's noise.
TEST_F(LaserWallTest, NoDropoutsTakeTheSameDrawsAsAnImpossibleDropout) {
  LaserOptions none;  // sigma 10 mm, dropout 0
  LaserOptions impossible = none;
  impossible.dropout_probability = 1e-300;  // below 2^-64, the smallest uniform but 0
  LaserSensor a(scene_, "laser", none, 11), b(scene_, "laser", impossible, 11);
  int returns = 0;
  for (int scan = 0; scan < 20; ++scan) {
    const ScanMeasurement ma = a.Measure(scene_, caster_), mb = b.Measure(scene_, caster_);
    ASSERT_EQ(ma.scan.ranges_m, mb.scan.ranges_m) << "scan " << scan;
    ASSERT_EQ(ma.hit_geom_ids, mb.hit_geom_ids) << "scan " << scan;
    for (std::size_t i = 0; i < ma.scan.ranges_m.size(); ++i) returns += ma.scan.IsReturn(i);
  }
  EXPECT_EQ(returns, 20 * (2 * 126 + 1));
}

// The room's interior before it is rotated about the world origin.
constexpr Rectangle kRoom{-2.0, 3.0, -1.5, 2.5};

TEST(LaserSensorSceneTest, NoiseFreeScanMatchesTheRoomAxisAlignedAndRotated) {
  const msgs::Pose2D X_room_R{0.3, 0.4, 20.0 * kDeg};  // robot pose in the room's frame
  for (const double room_yaw_deg : {0.0, 30.0}) {
    const double yaw = room_yaw_deg * kDeg;
    const msgs::Pose2D X_W_room{0.0, 0.0, yaw};
    const Scene scene(RobotIn(
        "p3dx",
        RoomWorld("laser_room_" + std::to_string(static_cast<int>(room_yaw_deg)), kRoom, yaw),
        X_W_room * X_room_R));
    const MujocoRayCaster caster(scene.model(), scene.data());
    LaserOptions options;
    options.noise_free = true;
    LaserSensor laser(scene, "laser", options, 1);
    const ScanMeasurement m = laser.Measure(scene, caster);
    // The laser site is 21 mm ahead of the robot's origin.
    const double px = X_room_R.x_m + 0.021 * std::cos(X_room_R.theta_rad);
    const double py = X_room_R.y_m + 0.021 * std::sin(X_room_R.theta_rad);
    for (std::size_t i = 0; i < m.scan.ranges_m.size(); ++i) {
      const auto [range_m, wall] =
          RoomRange(kRoom, px, py, X_room_R.theta_rad + m.scan.BeamAngleRad(i));
      EXPECT_NEAR(m.scan.ranges_m[i], range_m, 1e-3) << "room " << room_yaw_deg << " beam " << i;
      // Beams that end within a millimetre of a corner may name either wall.
      const double corner_margin = 1e-3;
      const auto [x, y] =
          std::pair{px + range_m * std::cos(X_room_R.theta_rad + m.scan.BeamAngleRad(i)),
                    py + range_m * std::sin(X_room_R.theta_rad + m.scan.BeamAngleRad(i))};
      const bool near_corner =
          (std::abs(x - 3.0) < corner_margin || std::abs(x + 2.0) < corner_margin) &&
          (std::abs(y - 2.5) < corner_margin || std::abs(y + 1.5) < corner_margin);
      if (!near_corner) {
        EXPECT_EQ(m.hit_geom_ids[i], mj_name2id(scene.model(), mjOBJ_GEOM, wall.c_str()))
            << "beam " << i << " should hit " << wall;
      }
    }
  }
}

}  // namespace
}  // namespace plywood::sim
