#include "sim/sonar_sensor.h"

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

SceneOptions P3dxIn(const std::filesystem::path& world, msgs::Pose2D spawn) {
  SceneOptions options;
  options.world_mjcf = world;
  options.robot_mjcf = SourceRoot() / "models" / "p3dx.xml";
  options.spawn = spawn;
  return options;
}

// One transducer (sonar_0) of a P3-DX facing a configurable set of walls given in its own frame.
class SonarGeometryTest : public ::testing::Test {
 protected:
  SonarGeometryTest()
      : scene_(P3dxIn(FloorWorld("sonar_geometry"), {0.5, -0.2, 25.0 * kDeg})),
        X_WS_(scene_.SitePoseInWorld(*scene_.FindSite("sonar_0"))) {
    options_.noise_free = true;
  }

  // A wall through (x, y) in the sensor frame whose normal (towards the sensor) points at
  // 180 + normal_offset_deg, i.e. the axis is normal_offset_deg off the wall's normal.
  Segment Wall(double x, double y, double normal_offset_deg, double half_length, int id) const {
    const double t = (90.0 + normal_offset_deg) * kDeg;
    return {ToWorld(X_WS_, x - half_length * std::cos(t), y - half_length * std::sin(t)),
            ToWorld(X_WS_, x + half_length * std::cos(t), y + half_length * std::sin(t)), id};
  }
  Segment Seg(double x0, double y0, double x1, double y1, int id) const {
    return {ToWorld(X_WS_, x0, y0), ToWorld(X_WS_, x1, y1), id};
  }

  msgs::RangeReading Read(const std::vector<Segment>& walls) {
    SonarSensor sonar(scene_, {"sonar_0"}, options_, 1);
    const msgs::RangeRing ring = sonar.Measure(scene_, SegmentCaster(walls));
    EXPECT_EQ(ring.readings.size(), 1u);
    return ring.readings.at(0);
  }

  Scene scene_;
  Eigen::Isometry3d X_WS_;
  SonarOptions options_;
};

TEST_F(SonarGeometryTest, PerpendicularWallEchoesAtItsDistance) {
  const msgs::RangeReading r = Read({Wall(2.0, 0.0, 0.0, 3.0, 1)});
  ASSERT_TRUE(r.echo);
  EXPECT_NEAR(r.range_m, 2.0, 1e-9);
  EXPECT_NEAR(r.X_RS.theta_rad, 90.0 * kDeg, 1e-9);  // sonar_0 looks left on the P3-DX
}

TEST_F(SonarGeometryTest, TiltedWallWithNormalInsideTheBeamEchoesFromItsNearestPoint) {
  // 12 deg off the normal falls between the fan's rays (0, 5, 10, 15 deg): the echo still comes
  // from the perpendicular foot at 2 m, not from the nearest ray (2 / cos 2 deg).
  const double t = 12.0 * kDeg;
  const msgs::RangeReading r = Read({Wall(2.0 * std::cos(t), 2.0 * std::sin(t), 12.0, 3.0, 1)});
  ASSERT_TRUE(r.echo);
  EXPECT_NEAR(r.range_m, 2.0, 1e-9);
}

TEST_F(SonarGeometryTest, ObliqueWallEchoesOnlyWithinTheIncidenceLimit) {
  // Wall normal 34 deg off the axis: the edge ray (15 deg) meets it at 19 deg <= 20 deg.
  const auto wall_at = [&](double offset_deg) {
    const double t = offset_deg * kDeg;
    return Wall(2.0 * std::cos(t), 2.0 * std::sin(t), offset_deg, 6.0, 1);
  };
  msgs::RangeReading r = Read({wall_at(34.0)});
  ASSERT_TRUE(r.echo);
  EXPECT_NEAR(r.range_m, 2.0 / std::cos(19.0 * kDeg), 1e-9);
  // 40 deg: the best ray meets it at 25 deg: a specular miss.
  r = Read({wall_at(40.0)});
  EXPECT_FALSE(r.echo);
}

// A 90 deg concave corner straight ahead at 2 m, walls at +-45 deg to the axis; 6 rays at
// +-3, +-9, +-15 deg so none hits the apex itself.
class SonarCornerTest : public SonarGeometryTest {
 protected:
  std::vector<Segment> Corner() const {
    return {Seg(2.0, 0.0, 0.0, 2.0, 1), Seg(2.0, 0.0, 0.0, -2.0, 2)};
  }
  static constexpr double kD = 2.0;
};

TEST_F(SonarCornerTest, CornerEchoComesBackAtAboutTheCornerDistance) {
  options_.rays_per_cone = 6;
  // Ray at angle a meets the wall x + y = D at t1 = D / (cos a + sin a), bounces to the other wall
  // (the unfolded path is D / (cos a - sin a)) and returns antiparallel; the echo is heard at half
  // of d1 + d2 + |p2|. The nearest comes from a = 3 deg.
  const double a = 3.0 * kDeg, c = std::cos(a), s = std::sin(a);
  const double t1 = kD / (c + s), unfolded = kD / (c - s);
  const Eigen::Vector2d p2 = t1 * Eigen::Vector2d(c, s) + (unfolded - t1) * Eigen::Vector2d(-s, -c);
  const double expected = (unfolded + p2.norm()) / 2.0;
  EXPECT_NEAR(expected, 2.0031, 1e-4);  // hand value for D = 2
  msgs::RangeReading r = Read(Corner());
  ASSERT_TRUE(r.echo);
  EXPECT_NEAR(r.range_m, expected, 1e-9);

  options_.corner_echoes = false;  // walls at >= 30 deg incidence: nothing comes back
  EXPECT_FALSE(Read(Corner()).echo);
}

TEST_F(SonarCornerTest, WithAWideIncidenceLimitTheNearestEchoingRayWins) {
  options_.rays_per_cone = 6;
  options_.incidence_limit_deg = 40.0;  // the 9 and 15 deg rays (36 and 30 deg incidence) echo
  options_.corner_echoes = false;
  const msgs::RangeReading r = Read(Corner());
  ASSERT_TRUE(r.echo);
  EXPECT_NEAR(r.range_m, kD / (std::cos(15.0 * kDeg) + std::sin(15.0 * kDeg)), 1e-9);
}

TEST_F(SonarCornerTest, CornerInsideTheBeamBesideAPerpendicularWallGivesTheNearestRange) {
  // Wall x = 2 meets the wall y = 0.3 at (2, 0.3), 8.5 deg off the axis; rays beyond it graze
  // y = 0.3 at >= 75 deg, and their corner echoes come from farther than 2 m.
  const msgs::RangeReading r = Read({Seg(2.0, -3.0, 2.0, 0.3, 1), Seg(0.5, 0.3, 2.0, 0.3, 2)});
  ASSERT_TRUE(r.echo);
  EXPECT_NEAR(r.range_m, 2.0, 1e-9);
}

TEST_F(SonarGeometryTest, MultipathGivesALongReadingAfterASpecularMiss) {
  // W1 through (2, 0) with normal (-cos 60, sin 60): the axis meets it at 60 deg, every ray at
  // >= 45 deg. The central ray reflects to heading 60 deg and meets the wall y = 1.5 after
  // d2 = 1.5 / sin 60 at p2 = (2 + d2 / 2, 1.5).
  const double r3 = std::sqrt(3.0);
  const std::vector<Segment> walls = {Seg(2.0 - 3.0 * r3 / 2.0, -1.5, 2.0 + 3.0 * r3 / 2.0, 1.5, 1),
                                      Seg(1.0, 1.5, 4.0, 1.5, 2)};
  EXPECT_FALSE(Read(walls).echo);
  options_.multipath = true;
  const double d2 = 1.5 / std::sin(60.0 * kDeg);
  const double expected = (2.0 + d2 + std::hypot(2.0 + d2 / 2.0, 1.5)) / 2.0;
  EXPECT_NEAR(expected, 3.4834, 1e-4);
  const msgs::RangeReading r = Read(walls);
  ASSERT_TRUE(r.echo);
  EXPECT_NEAR(r.range_m, expected, 1e-9);
}

TEST_F(SonarGeometryTest, RangeLimits) {
  msgs::RangeReading r = Read({Wall(0.1, 0.0, 0.0, 1.0, 1)});
  ASSERT_TRUE(r.echo);
  EXPECT_EQ(r.range_m, 0.15);  // inside the blanking distance: reported as range_min_m
  EXPECT_FALSE(Read({Wall(5.5, 0.0, 0.0, 3.0, 1)}).echo);
  EXPECT_FALSE(Read({}).echo);
}

TEST(SonarSensorTest, NoiseIsOnePercentOfRangeAndZeroMean) {
  Scene scene(P3dxIn(FloorWorld("sonar_noise"), {0.2, 0.1, 10.0 * kDeg}));
  // A 4 x 3 m box around the robot.
  const SegmentCaster caster({{{-1.8, -1.4}, {2.2, -1.4}, 1},
                              {{2.2, -1.4}, {2.2, 1.6}, 2},
                              {{2.2, 1.6}, {-1.8, 1.6}, 3},
                              {{-1.8, 1.6}, {-1.8, -1.4}, 4}});
  SonarOptions options;
  SonarOptions exact = options;
  exact.noise_free = true;
  SonarSensor noisy(scene, SonarSensor::DefaultSiteNames(), options, 9);
  SonarSensor clean(scene, SonarSensor::DefaultSiteNames(), exact, 1);
  const msgs::RangeRing truth = clean.Measure(scene, caster);
  double sum = 0.0, sum_sq = 0.0;
  int n = 0;
  while (n < 20000) {
    const msgs::RangeRing ring = noisy.Measure(scene, caster);
    ASSERT_EQ(ring.readings.size(), 16u);
    for (std::size_t k = 0; k < 16; ++k) {
      if (!truth.readings[k].echo) continue;
      ASSERT_TRUE(ring.readings[k].echo);
      const double z = (ring.readings[k].range_m - truth.readings[k].range_m) /
                       (0.01 * truth.readings[k].range_m);
      sum += z;
      sum_sq += z * z;
      ++n;
    }
  }
  const double mean = sum / n, sigma = std::sqrt(sum_sq / n - mean * mean);
  EXPECT_LT(std::abs(mean), 0.05);
  EXPECT_NEAR(sigma, 1.0, 0.05);
}

TEST(SonarSensorTest, MissingSiteIsAConfigErrorNamingTheSite) {
  Scene scene(P3dxIn(FloorWorld("sonar_missing"), {}));
  try {
    SonarSensor sonar(scene, {"sonar_0", "sonar_16"}, SonarOptions{}, 1);
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("sonar_16"), std::string::npos) << e.what();
  }
}

TEST(SonarOptionsTest, ValidateNamesTheField) {
  const auto expect_field = [](SonarOptions o, const std::string& field) {
    try {
      o.Validate();
      ADD_FAILURE() << field << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(field + ":", 0), 0u) << e.what();
    }
  };
  EXPECT_NO_THROW(SonarOptions{}.Validate());
  SonarOptions o;
  o.beam_half_angle_deg = 95.0;
  expect_field(o, "beam_half_angle_deg");
  o = {};
  o.rays_per_cone = 0;
  expect_field(o, "rays_per_cone");
  o = {};
  o.incidence_limit_deg = -1.0;
  expect_field(o, "incidence_limit_deg");
  o = {};
  o.range_min_m = 6.0;
  expect_field(o, "range_min_m");
  o = {};
  o.range_max_m = 0.0;
  expect_field(o, "range_max_m");
  o = {};
  o.range_noise_fraction = -0.01;
  expect_field(o, "range_noise_fraction");
  o = {};
  o.rate_hz = 0.0;
  expect_field(o, "rate_hz");
}

// The P3-DX in a real MuJoCo room: interior [-2, 3] x [-1.5, 2.5], optionally rotated.
TEST(SonarSensorSceneTest, SideSonarsReadTheWallsTheyFaceInAxisAlignedAndRotatedRooms) {
  for (const double yaw_deg : {0.0, 30.0}) {
    const double yaw = yaw_deg * kDeg, c = std::cos(yaw), s = std::sin(yaw);
    std::string xml =
        "<mujoco><worldbody><geom name=\"floor\" type=\"plane\" size=\"10 10 0.1\"/>\n";
    const double walls[4][4] = {{3.05, 0.5, 0.05, 2.2},
                                {-2.05, 0.5, 0.05, 2.2},
                                {0.5, 2.55, 2.7, 0.05},
                                {0.5, -1.55, 2.7, 0.05}};
    for (const auto& w : walls) {
      xml += "<geom type=\"box\" pos=\"" + std::to_string(c * w[0] - s * w[1]) + " " +
             std::to_string(s * w[0] + c * w[1]) + " 0.5\" size=\"" + std::to_string(w[2]) + " " +
             std::to_string(w[3]) + " 0.5\" euler=\"0 0 " + std::to_string(yaw_deg) + "\"/>\n";
    }
    xml += "</worldbody></mujoco>\n";
    const auto world =
        WriteFile(MakeTempDir("sonar_room_" + std::to_string(int(yaw_deg))) / "room.xml", xml);
    const msgs::Pose2D X_room_R{0.3, 0.4, 0.0};
    const Scene scene(P3dxIn(world, msgs::Pose2D{0.0, 0.0, yaw} * X_room_R));
    const MujocoRayCaster caster(scene.model(), scene.data());
    SonarOptions options;
    options.noise_free = true;
    SonarSensor sonar(scene, {"sonar_0", "sonar_7", "sonar_15"}, options, 1);
    const msgs::RangeRing ring = sonar.Measure(scene, caster);
    // sonar_0 (0.069, 0.136) and sonar_15 (-0.157, 0.136) face +y; sonar_7 (0.069, -0.136) faces
    // -y.
    ASSERT_TRUE(ring.readings[0].echo && ring.readings[1].echo && ring.readings[2].echo);
    EXPECT_NEAR(ring.readings[0].range_m, 2.5 - 0.4 - 0.136, 1e-6);
    EXPECT_NEAR(ring.readings[1].range_m, 1.5 + 0.4 - 0.136, 1e-6);
    EXPECT_NEAR(ring.readings[2].range_m, 2.5 - 0.4 - 0.136, 1e-6);
  }
}

}  // namespace
}  // namespace plywood::sim
