#include "sim/ir_ring_sensor.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/config_error.h"
#include "sim/mujoco_ray_caster.h"
#include "sim/scene.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::sim {
namespace {

using plywood::testing::MakeTempDir;
using plywood::testing::SourceRoot;
using plywood::testing::WriteFile;

constexpr double kDeg = std::numbers::pi / 180.0;

// Walls as 2-D segments of unbounded height: exact ranges and normals for the unit tests.
struct Segment {
  Eigen::Vector2d a, b;
  int geom_id;
};

class SegmentCaster : public RayCaster {
 public:
  explicit SegmentCaster(std::vector<Segment> segments) : segments_(std::move(segments)) {}

  bool Cast(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W, double max_range_m,
            RayHit* hit) const override {
    const Eigen::Vector2d o = origin_W.head<2>(), d = dir_W.head<2>();
    const auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
      return u.x() * v.y() - u.y() * v.x();
    };
    bool found = false;
    for (const Segment& s : segments_) {
      const Eigen::Vector2d e = s.b - s.a, w = s.a - o;
      const double denom = cross(d, e);
      if (std::abs(denom) < 1e-15) continue;
      const double t = cross(w, e) / denom, u = cross(w, d) / denom;
      if (t <= 1e-12 || u < 0.0 || u > 1.0 || t > max_range_m) continue;
      if (found && t >= hit->distance_m) continue;
      found = true;
      Eigen::Vector2d n(-e.y(), e.x());
      n.normalize();
      if (n.dot(d) > 0.0) n = -n;
      hit->distance_m = t;
      hit->geom_id = s.geom_id;
      hit->normal_W = Eigen::Vector3d(n.x(), n.y(), 0.0);
    }
    return found;
  }

 private:
  std::vector<Segment> segments_;
};

// A point given in the sensor's planar frame, in the world.
Eigen::Vector2d ToWorld(const Eigen::Isometry3d& X_WS, double x, double y) {
  return (X_WS * Eigen::Vector3d(x, y, 0.0)).head<2>();
}

std::filesystem::path FloorWorld(const std::string& name) {
  return WriteFile(MakeTempDir(name) / "floor.xml", R"(<mujoco>
  <worldbody><geom name="floor" type="plane" size="10 10 0.1"/></worldbody>
</mujoco>
)");
}

SceneOptions RobotIn(const std::string& robot, const std::filesystem::path& world,
                     msgs::Pose2D spawn) {
  SceneOptions options;
  options.world_mjcf = world;
  options.robot_mjcf = SourceRoot() / "models" / (robot + ".xml");
  options.spawn = spawn;
  return options;
}

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
  double sum = 0.0, sum_sq = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double e = ir.Measure(scene_, caster).readings[0].range_m - 0.4;
    sum += e;
    sum_sq += e * e;
  }
  const double mean = sum / n, sigma = std::sqrt(sum_sq / n - mean * mean);
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
  const auto expect_field = [](IrRingOptions o, const std::string& field) {
    try {
      o.Validate();
      ADD_FAILURE() << field << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(field + ":", 0), 0u) << e.what();
    }
  };
  EXPECT_NO_THROW(IrRingOptions{}.Validate());
  IrRingOptions o;
  o.rays_per_beam = 0;
  expect_field(o, "rays_per_beam");
  o = {};
  o.range_min_m = 0.9;
  expect_field(o, "range_min_m");
  o = {};
  o.sigma_m = -1.0;
  expect_field(o, "sigma_m");
  o = {};
  o.incidence_limit_deg = 100.0;
  expect_field(o, "incidence_limit_deg");
  o = {};
  o.rate_hz = -2.0;
  expect_field(o, "rate_hz");
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
