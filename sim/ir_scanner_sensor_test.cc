#include "sim/ir_scanner_sensor.h"

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

// The Magellan Pro inside a 4 x 3 m box given as segments, walls at distances from the scanner.
class IrScannerTest : public ::testing::Test {
 protected:
  IrScannerTest()
      : scene_(RobotIn("magellan_pro", FloorWorld("ir_scanner"), {0.0, 0.0, 0.0})),
        p_(scene_.SitePoseInWorld(*scene_.FindSite("ir_scanner")).translation().head<2>()),
        caster_({{{-1.5, -1.0}, {2.5, -1.0}, 1},
                 {{2.5, -1.0}, {2.5, 2.0}, 2},
                 {{2.5, 2.0}, {-1.5, 2.0}, 3},
                 {{-1.5, 2.0}, {-1.5, -1.0}, 4}}) {}

  // The box's boundary from the scanner (at the robot's origin, heading 0) along heading phi.
  double TrueRange(double phi) const {
    const double c = std::cos(phi), s = std::sin(phi);
    double t = 1e9;
    if (c > 1e-12) t = std::min(t, (2.5 - p_.x()) / c);
    if (c < -1e-12) t = std::min(t, (-1.5 - p_.x()) / c);
    if (s > 1e-12) t = std::min(t, (2.0 - p_.y()) / s);
    if (s < -1e-12) t = std::min(t, (-1.0 - p_.y()) / s);
    return t;
  }

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
  double sum = 0.0, sum_sq = 0.0;
  int n = 0;
  while (n < 20000) {
    const ScanMeasurement m = scanner.Measure(scene_, caster_);
    for (std::size_t i = 0; i < m.scan.ranges_m.size(); ++i) {
      const double expected = TrueRange(m.scan.BeamAngleRad(i));
      if (expected > 2.9) continue;
      const double e = m.scan.ranges_m[i] - expected;
      sum += e;
      sum_sq += e * e;
      ++n;
    }
  }
  const double mean = sum / n, sigma = std::sqrt(sum_sq / n - mean * mean);
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
  const auto expect_field = [](IrScannerOptions o, const std::string& field) {
    try {
      o.Validate();
      ADD_FAILURE() << field << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(field + ":", 0), 0u) << e.what();
    }
  };
  EXPECT_NO_THROW(IrScannerOptions{}.Validate());
  EXPECT_EQ(IrScannerOptions{}.BeamCount(), 200);
  IrScannerOptions o;
  o.fov_deg = 180.0;
  EXPECT_EQ(o.BeamCount(), 101);  // a partial sweep includes both ends
  o = {};
  o.fov_deg = 400.0;
  expect_field(o, "fov_deg");
  o = {};
  o.resolution_deg = 1.7;
  expect_field(o, "fov_deg");
  o = {};
  o.resolution_deg = 0.0;
  expect_field(o, "resolution_deg");
  o = {};
  o.sigma_m = -0.1;
  expect_field(o, "sigma_m");
  o = {};
  o.outlier_probability = 2.0;
  expect_field(o, "outlier_probability");
  o = {};
  o.range_min_m = 3.5;
  expect_field(o, "range_min_m");
  o = {};
  o.rate_hz = 0.0;
  expect_field(o, "rate_hz");
}

TEST(IrScannerSensorSceneTest, NoiseFreeTurnMatchesAMujocoRoom) {
  const auto world = WriteFile(MakeTempDir("ir_scanner_scene") / "room.xml", R"(<mujoco><worldbody>
  <geom name="floor" type="plane" size="5 5 0.1"/>
  <geom name="east" type="box" pos="1.25 0 0.5" size="0.05 2 0.5"/>
  <geom name="west" type="box" pos="-1.05 0 0.5" size="0.05 2 0.5"/>
  <geom name="north" type="box" pos="0 1.05 0.5" size="2 0.05 0.5"/>
  <geom name="south" type="box" pos="0 -0.85 0.5" size="2 0.05 0.5"/>
</worldbody></mujoco>
)");
  const Scene scene(RobotIn("magellan_pro", world, {}));
  IrScannerOptions options;
  options.noise_free = true;
  IrScannerSensor scanner(scene, "ir_scanner", options, 1);
  const ScanMeasurement m = scanner.Measure(scene, MujocoRayCaster(scene.model(), scene.data()));
  for (std::size_t i = 0; i < m.scan.ranges_m.size(); ++i) {
    const double c = std::cos(m.scan.BeamAngleRad(i)), s = std::sin(m.scan.BeamAngleRad(i));
    double t = 1e9;
    if (c > 1e-12) t = std::min(t, 1.2 / c);
    if (c < -1e-12) t = std::min(t, -1.0 / c);
    if (s > 1e-12) t = std::min(t, 1.0 / s);
    if (s < -1e-12) t = std::min(t, -0.8 / s);
    EXPECT_NEAR(m.scan.ranges_m[i], t, 1e-6) << i;
  }
}

}  // namespace
}  // namespace plywood::sim
