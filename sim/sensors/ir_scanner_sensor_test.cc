#include "sim/sensors/ir_scanner_sensor.h"

#include <gtest/gtest.h>

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
using plywood::testing::RoomSegments;
using plywood::testing::RoomWorld;
using plywood::testing::SampleStats;
using plywood::testing::SegmentCaster;

constexpr double kDeg = std::numbers::pi / 180.0;

// The Magellan Pro inside a 4 x 3 m box given as segments, walls at distances from the scanner.
class IrScannerTest : public ::testing::Test {
 protected:
  IrScannerTest()
      : scene_(RobotIn("magellan_pro", FloorWorld("ir_scanner"), {0.0, 0.0, 0.0})),
        p_(scene_.SitePoseInWorld(*scene_.FindSite("ir_scanner")).translation().head<2>()),
        caster_(RoomSegments(kBox)) {}

  // The box's boundary from the scanner (at the robot's origin, heading 0) along heading phi.
  double TrueRange(double phi) const { return RoomRange(kBox, p_.x(), p_.y(), phi).first; }

  static constexpr Rectangle kBox{-1.5, 2.5, -1.0, 2.0};

  Scene scene_;
  Eigen::Vector2d p_;
  SegmentCaster caster_;
};

TEST_F(IrScannerTest, NoiseFreeTurnHas200BeamsMatchingTheRoom) {
  IrScannerOptions options;
  options.noise_free = true;
  IrScannerSensor scanner(scene_, "ir_scanner", options, 1);
  const ScanMeasurement m = scanner.Measure(scene_, caster_);
  ASSERT_EQ(m.scan.ranges_m.size(), 200u);
  EXPECT_DOUBLE_EQ(m.scan.angle_min_rad, -std::numbers::pi);
  EXPECT_DOUBLE_EQ(m.scan.angle_increment_rad, 1.8 * kDeg);
  int returns = 0;
  for (std::size_t i = 0; i < 200; ++i) {
    const double expected = TrueRange(m.scan.BeamAngleRad(i));
    if (expected < 3.0) {
      ++returns;
      EXPECT_NEAR(m.scan.ranges_m[i], expected, 1e-9) << i;
      EXPECT_GE(m.hit_geom_ids[i], 1);
    } else {
      EXPECT_EQ(m.scan.ranges_m[i], 3.0) << i;
      EXPECT_EQ(m.hit_geom_ids[i], -1);
    }
  }
  EXPECT_GT(returns, 150);
  EXPECT_LT(returns, 200);  // the far corners are beyond 3 m
}

TEST_F(IrScannerTest, OutlierRateMatchesAndOutliersAreUniform) {
  IrScannerOptions options;
  options.sigma_m = 0.0;
  options.outlier_probability = 0.01;
  IrScannerSensor scanner(scene_, "ir_scanner", options, 17);
  int beams = 0, outliers = 0;
  double outlier_sum = 0.0;
  for (int turn = 0; turn < 250; ++turn) {
    const ScanMeasurement m = scanner.Measure(scene_, caster_);
    for (std::size_t i = 0; i < m.scan.ranges_m.size(); ++i) {
      ++beams;
      const double expected = std::min(3.0, TrueRange(m.scan.BeamAngleRad(i)));
      if (std::abs(m.scan.ranges_m[i] - expected) > 1e-9) {
        ++outliers;
        outlier_sum += m.scan.ranges_m[i];
        EXPECT_EQ(m.hit_geom_ids[i], -1);
        EXPECT_GE(m.scan.ranges_m[i], 0.1);
        EXPECT_LT(m.scan.ranges_m[i], 3.0);
      }
    }
  }
  // 50,000 beams: the rate's standard error is 0.00045; 500 uniform outliers average 1.55 m with
  // a standard error of 0.037 m.
  EXPECT_NEAR(static_cast<double>(outliers) / beams, 0.01, 0.002);
  EXPECT_NEAR(outlier_sum / outliers, 1.55, 0.15);
}

TEST_F(IrScannerTest, RangeNoiseHasTheConfiguredSigma) {
  IrScannerOptions options;
  options.outlier_probability = 0.0;
  IrScannerSensor scanner(scene_, "ir_scanner", options, 23);
  SampleStats stats;
  while (stats.count() < 20000) {
    const ScanMeasurement m = scanner.Measure(scene_, caster_);
    for (std::size_t i = 0; i < m.scan.ranges_m.size(); ++i) {
      const double expected = TrueRange(m.scan.BeamAngleRad(i));
      if (expected > 2.9) continue;
      const double e = m.scan.ranges_m[i] - expected;
      stats.Add(e);
    }
  }
  const double mean = stats.Mean(), sigma = stats.Sigma();
  EXPECT_LT(std::abs(mean), 0.05 * 0.005);
  EXPECT_NEAR(sigma, 0.005, 0.05 * 0.005);
}

TEST(IrScannerSensorTest, MissingSiteIsAConfigErrorNamingTheSite) {
  const Scene scene(RobotIn("p3dx", FloorWorld("ir_scanner_missing"), {}));
  try {
    IrScannerSensor scanner(scene, "ir_scanner", IrScannerOptions{}, 1);
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("ir_scanner"), std::string::npos) << e.what();
  }
}

TEST(IrScannerOptionsTest, ValidateNamesTheFieldAndCountsBeams) {
  EXPECT_NO_THROW(IrScannerOptions{}.Validate());
  EXPECT_EQ(IrScannerOptions{}.BeamCount(), 200);
  EXPECT_EQ(IrScannerOptions{.fov_deg = 180.0}.BeamCount(),
            101);  // a partial sweep includes both ends
  ExpectInvalidField(IrScannerOptions{.fov_deg = 400.0}, "fov_deg");
  ExpectInvalidField(IrScannerOptions{.resolution_deg = 1.7}, "fov_deg");
  ExpectInvalidField(IrScannerOptions{.resolution_deg = 0.0}, "resolution_deg");
  // s50: 1e-300 deg overflowed the beam count into a 0-beam scanner that ran (exit 0), 1e-9
  // ended on "vector::reserve", 1e-6 never finished; 0.01 deg (36000 beams) is the finest.
  for (const double fine : {1e-300, 1e-9, 1e-6, 0.009}) {
    SCOPED_TRACE(fine);
    ExpectInvalidField(IrScannerOptions{.resolution_deg = fine}, "resolution_deg");
  }
  EXPECT_NO_THROW(IrScannerOptions{.resolution_deg = 0.01}.Validate());
  EXPECT_EQ(IrScannerOptions{.resolution_deg = 0.01}.BeamCount(), 36000);
  ExpectInvalidField(IrScannerOptions{.sigma_m = -0.1}, "sigma_m");
  ExpectInvalidField(IrScannerOptions{.outlier_probability = 2.0}, "outlier_probability");
  ExpectInvalidField(IrScannerOptions{.range_min_m = 3.5}, "range_min_m");
  ExpectInvalidField(IrScannerOptions{.rate_hz = 0.0}, "rate_hz");
}

TEST(IrScannerSensorSceneTest, NoiseFreeTurnMatchesAMujocoRoom) {
  // The scanner sits above the robot's origin.
  constexpr Rectangle kRoom{-1.0, 1.2, -0.8, 1.0};
  const auto world = RoomWorld("ir_scanner_scene", kRoom);
  const Scene scene(RobotIn("magellan_pro", world, {}));
  IrScannerOptions options;
  options.noise_free = true;
  IrScannerSensor scanner(scene, "ir_scanner", options, 1);
  const ScanMeasurement m = scanner.Measure(scene, MujocoRayCaster(scene.model(), scene.data()));
  for (std::size_t i = 0; i < m.scan.ranges_m.size(); ++i) {
    const double t = RoomRange(kRoom, 0.0, 0.0, m.scan.BeamAngleRad(i)).first;
    EXPECT_NEAR(m.scan.ranges_m[i], t, 1e-6) << i;
  }
}

}  // namespace
}  // namespace plywood::sim
