#include "sim/sensors/ir_ring_sensor.h"

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
#include "tests/support/mujoco_test_support.h"
#include "tests/support/options_test_support.h"
#include "tests/support/sample_stats.h"
#include "tests/support/sensor_test_support.h"

namespace plywood::sim {
namespace {

using plywood::testing::ExpectInvalidField;
using plywood::testing::FloorWorld;
using plywood::testing::MakeTempDir;
using plywood::testing::RobotIn;
using plywood::testing::SampleStats;
using plywood::testing::Segment;
using plywood::testing::SegmentCaster;
using plywood::testing::ToWorld;
using plywood::testing::WriteFile;

constexpr double kDeg = std::numbers::pi / 180.0;

class IrRingTest : public ::testing::Test {
 protected:
  IrRingTest()
      : scene_(RobotIn("magellan_pro", FloorWorld("ir_ring"), {-0.3, 0.7, -40.0 * kDeg})),
        X_WS_(scene_.SitePoseInWorld(*scene_.FindSite("ir_0"))) {
    options_.noise_free = true;
  }
  // A wall in ir_0's frame through (d, 0) whose normal is offset_deg off the beam axis.
  Segment Wall(double d, double offset_deg) const {
    const double t = (90.0 + offset_deg) * kDeg;
    const double x = d * std::cos(offset_deg * kDeg), y = d * std::sin(offset_deg * kDeg);
    return {ToWorld(X_WS_, x - 2.0 * std::cos(t), y - 2.0 * std::sin(t)),
            ToWorld(X_WS_, x + 2.0 * std::cos(t), y + 2.0 * std::sin(t)), 1};
  }
  msgs::RangeReading Read(const std::vector<Segment>& walls) {
    IrRingSensor ir(scene_, {"ir_0"}, options_, 3);
    return ir.Measure(scene_, SegmentCaster(walls)).readings.at(0);
  }
  Scene scene_;
  Eigen::Isometry3d X_WS_;
  IrRingOptions options_;
};

TEST_F(IrRingTest, PerpendicularWallReadsItsDistanceWithinRange) {
  msgs::RangeReading r = Read({Wall(0.5, 0.0)});
  ASSERT_TRUE(r.echo);
  EXPECT_NEAR(r.range_m, 0.5, 1e-9);
  EXPECT_FALSE(Read({Wall(0.85, 0.0)}).echo);
  r = Read({Wall(0.05, 0.0)});
  ASSERT_TRUE(r.echo);
  EXPECT_EQ(r.range_m, 0.1);
}

TEST_F(IrRingTest, OnlyGrazingHitsBeyondTheIncidenceLimitAreLost) {
  // The single axial ray meets a wall whose normal is offset by o at incidence o, at range
  // d / cos(o) for a wall whose foot is at distance d.
  msgs::RangeReading r = Read({Wall(0.2, 70.0)});
  ASSERT_TRUE(r.echo);
  EXPECT_NEAR(r.range_m, 0.2 / std::cos(70.0 * kDeg), 1e-9);
  EXPECT_FALSE(Read({Wall(0.1, 80.0)}).echo);
}

TEST_F(IrRingTest, ThreeRayBeamReportsTheNearestRay) {
  options_.rays_per_beam = 3;  // at -2, 0, +2 deg
  // Wall normal 30 deg off the axis with its foot at 0.4 m: the +2 deg ray is nearest,
  // at 0.4 / cos(28 deg).
  const msgs::RangeReading r = Read({Wall(0.4, 30.0)});
  ASSERT_TRUE(r.echo);
  EXPECT_NEAR(r.range_m, 0.4 / std::cos(28.0 * kDeg), 1e-9);
}

TEST_F(IrRingTest, NoiseHasTheConfiguredSigma) {
  options_.noise_free = false;
  IrRingSensor ir(scene_, {"ir_0"}, options_, 5);
  const SegmentCaster caster({Wall(0.4, 0.0)});
  SampleStats stats;
  for (int i = 0; i < 20000; ++i) stats.Add(ir.Measure(scene_, caster).readings[0].range_m - 0.4);
  const double mean = stats.Mean(), sigma = stats.Sigma();
  EXPECT_LT(std::abs(mean), 0.05 * 0.01);
  EXPECT_NEAR(sigma, 0.01, 0.05 * 0.01);
}

TEST(IrRingSensorTest, MissingSiteIsAConfigErrorNamingTheSite) {
  const Scene scene(RobotIn("p3dx", FloorWorld("ir_ring_missing"), {}));  // the P3-DX has no IR
  try {
    IrRingSensor ir(scene, IrRingSensor::DefaultSiteNames(), IrRingOptions{}, 1);
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("ir_0"), std::string::npos) << e.what();
  }
}

TEST(IrRingOptionsTest, ValidateNamesTheField) {
  EXPECT_NO_THROW(IrRingOptions{}.Validate());
  ExpectInvalidField(IrRingOptions{.rays_per_beam = 0}, "rays_per_beam");
  ExpectInvalidField(IrRingOptions{.range_min_m = 0.9}, "range_min_m");
  ExpectInvalidField(IrRingOptions{.sigma_m = -1.0}, "sigma_m");
  ExpectInvalidField(IrRingOptions{.incidence_limit_deg = 100.0}, "incidence_limit_deg");
  ExpectInvalidField(IrRingOptions{.rate_hz = -2.0}, "rate_hz");
}

TEST(IrRingSensorSceneTest, FrontAndSideEmittersReadAMujocoWall) {
  const auto world = WriteFile(MakeTempDir("ir_ring_scene") / "wall.xml", R"(<mujoco><worldbody>
  <geom name="floor" type="plane" size="5 5 0.1"/>
  <geom name="wall" type="box" pos="0.75 0 0.5" size="0.05 2 0.5"/>
</worldbody></mujoco>
)");
  const Scene scene(RobotIn("magellan_pro", world, {}));
  IrRingOptions options;
  options.noise_free = true;
  IrRingSensor ir(scene, IrRingSensor::DefaultSiteNames(), options, 1);
  const msgs::RangeRing ring = ir.Measure(scene, MujocoRayCaster(scene.model(), scene.data()));
  ASSERT_EQ(ring.readings.size(), 16u);
  ASSERT_TRUE(ring.readings[0].echo);
  EXPECT_NEAR(ring.readings[0].range_m, 0.7 - 0.203, 1e-6);
  // ir_1 at 22.5 deg from (0.1875, 0.0777): (0.7 - 0.1875) / cos 22.5.
  ASSERT_TRUE(ring.readings[1].echo);
  EXPECT_NEAR(ring.readings[1].range_m, (0.7 - 0.1875) / std::cos(22.5 * kDeg), 1e-6);
  EXPECT_FALSE(ring.readings[8].echo);  // facing away
}

}  // namespace
}  // namespace plywood::sim
