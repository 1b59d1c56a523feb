#include "sim/sensors/sonar_sensor.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/config/config_error.h"
#include "sim/raycast/grid_ray_caster_2d.h"
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
using plywood::testing::Rectangle;
using plywood::testing::RobotIn;
using plywood::testing::RoomSegments;
using plywood::testing::RoomWorld;
using plywood::testing::SampleStats;
using plywood::testing::Segment;
using plywood::testing::SegmentCaster;
using plywood::testing::SourceRoot;
using plywood::testing::ToWorld;
using plywood::testing::WriteFile;

constexpr double kDeg = std::numbers::pi / 180.0;

// One transducer (sonar_0) of a P3-DX facing a configurable set of walls given in its own frame.
class SonarGeometryTest : public ::testing::Test {
 protected:
  SonarGeometryTest()
      : scene_(RobotIn("p3dx", FloorWorld("sonar_geometry"), {0.5, -0.2, 25.0 * kDeg})),
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

// Boxes 1 m high on the floor of a real MuJoCo world around sonar_0 of a P3-DX parked at
// kSpawn, given in that transducer's planar frame; noise-free readings against MujocoRayCaster.
class SonarEdgeTest : public ::testing::Test {
 protected:
  struct Box {
    double x, y, half_x, half_y, yaw_deg;  // centre and yaw in the sensor frame
  };
  static constexpr msgs::Pose2D kSpawn{0.5, -0.2, 25.0 * kDeg};

  SonarEdgeTest() : X_WS_(Sonar0Pose()) { options_.noise_free = true; }

  static Eigen::Isometry3d Sonar0Pose() {
    const Scene scene(RobotIn("p3dx", FloorWorld("sonar_edge_floor"), kSpawn));
    return scene.SitePoseInWorld(*scene.FindSite("sonar_0"));
  }

  // A box of half size h whose nearest corner lies range_m along bearing_deg from the
  // transducer, the bisector of its two faces there pointing back at the transducer: both faces
  // meet the line of sight at 45 deg.
  static Box DiagonalBox(double range_m, double bearing_deg, double h = 0.3) {
    const double b = bearing_deg * kDeg, centre_m = range_m + h * std::sqrt(2.0);
    return {centre_m * std::cos(b), centre_m * std::sin(b), h, h, bearing_deg - 45.0};
  }

  msgs::RangeReading Read(const std::vector<Box>& boxes) {
    const double yaw_S = std::atan2(X_WS_.linear()(1, 0), X_WS_.linear()(0, 0));
    std::string xml = "<mujoco>\n  <worldbody>\n    <geom type=\"plane\" size=\"10 10 0.1\"/>\n";
    for (const Box& box : boxes) {
      const Eigen::Vector2d c = ToWorld(X_WS_, box.x, box.y);
      xml += "    <geom type=\"box\" pos=\"" + std::to_string(c.x()) + " " + std::to_string(c.y()) +
             " 0.5\" size=\"" + std::to_string(box.half_x) + " " + std::to_string(box.half_y) +
             " 0.5\" euler=\"0 0 " + std::to_string(box.yaw_deg + yaw_S / kDeg) + "\"/>\n";
    }
    xml += "  </worldbody>\n</mujoco>\n";
    const Scene scene(RobotIn(
        "p3dx", WriteFile(MakeTempDir("sonar_edge_" + std::to_string(++worlds_)) / "w.xml", xml),
        kSpawn));
    const MujocoRayCaster caster(scene.model(), scene.data());
    SonarSensor sonar(scene, {"sonar_0"}, options_, 1);
    return sonar.Measure(scene, caster).readings.at(0);
  }

  // The horizontal distance from the transducer to the point (x, y) of its planar frame, as the
  // world file's rounding (6 decimals) placed it.
  double RangeTo(const Box& box, double corner_x_G, double corner_y_G) const {
    const double yaw = box.yaw_deg * kDeg;
    const double x = box.x + std::cos(yaw) * corner_x_G - std::sin(yaw) * corner_y_G;
    const double y = box.y + std::sin(yaw) * corner_x_G + std::cos(yaw) * corner_y_G;
    return std::hypot(x, y);
  }

  Eigen::Isometry3d X_WS_;
  SonarOptions options_;
  int worlds_ = 0;
};

TEST_F(SonarEdgeTest, ABoxCornerMetOnItsBisectorIsHeardAtItsDistanceOnlyWithEdgeEchoes) {
  // Both faces at 45 deg to the axis: every ray meets them at 30-60 deg incidence (beyond the
  // 20 deg limit), their normals lie 45 deg off the axis (no foot in the beam), and a convex
  // corner sends no double bounce back: silent without the option.
  const Box box = DiagonalBox(1.0, 0.0);
  EXPECT_FALSE(Read({box}).echo);
  options_.edge_echoes = true;
  const msgs::RangeReading r = Read({box});
  ASSERT_TRUE(r.echo);
  EXPECT_NEAR(r.range_m, 1.0, 1e-5);  // the world file keeps 6 decimals
}

TEST_F(SonarEdgeTest, AnEdgeBeyondItsAudibleRangeIsNotHeard) {
  options_.edge_echoes = true;
  options_.edge_echo_range_m = 0.99;
  EXPECT_FALSE(Read({DiagonalBox(1.0, 0.0)}).echo);
  options_.edge_echo_range_m = 1.01;
  EXPECT_TRUE(Read({DiagonalBox(1.0, 0.0)}).echo);
  options_ = SonarOptions{.edge_echoes = true, .noise_free = true};  // 2.3 m
  EXPECT_FALSE(Read({DiagonalBox(2.4, 0.0)}).echo);
  EXPECT_NEAR(Read({DiagonalBox(2.2, 0.0)}).range_m, 2.2, 1e-5);
}

TEST_F(SonarEdgeTest, AnEdgeOutsideTheBeamIsNotHeard) {
  options_.edge_echoes = true;
  // 10 deg off the axis, inside the 15 deg half-angle: heard at its distance (the rays meet its
  // faces at 30-45 deg; its side corner at -6.6 deg is farther).
  const msgs::RangeReading r = Read({DiagonalBox(1.2, 10.0)});
  ASSERT_TRUE(r.echo);
  EXPECT_NEAR(r.range_m, 1.2, 1e-5);
  // 20 deg off: outside. A 2 x 2 m box, so its side corners (8.4 deg off) lie 2.97 m away, beyond
  // the edge range; the rays meet its near face at 50-73 deg.
  EXPECT_FALSE(Read({DiagonalBox(1.2, 20.0, 1.0)}).echo);
  EXPECT_FALSE(Read({DiagonalBox(1.2, -20.0, 1.0)}).echo);
}

TEST_F(SonarEdgeTest, AnEdgeHiddenBehindAnotherBoxIsNotHeard) {
  options_.edge_echoes = true;
  const Box corner = DiagonalBox(1.5, 0.0);
  ASSERT_TRUE(Read({corner}).echo);
  // A thin 3 m slab across the axis at 0.8 m, its faces at 45 deg to the axis (silent as above)
  // and its ends far outside the beam, stands between the transducer and the corner.
  const Box slab{0.8, 0.0, 0.02, 1.5, 45.0};
  EXPECT_FALSE(Read({slab, corner}).echo);
}

TEST_F(SonarEdgeTest, ABoxCornerFlushAgainstAWallIsNoEdge) {
  options_.edge_echoes = true;
  // The wall's face runs through C = (1, 0) at 45 deg to the axis; a 1.0 x 0.4 m box stands flush
  // against it, its corner at C, the rest of it off the beam (its free corners 21-35 deg off the
  // axis). The box's side and the wall make a concave corner at C, whose own echo is the corner
  // model's (off here): the edge at C is buried in the wall and sends nothing.
  options_.corner_echoes = false;
  const double r2 = std::sqrt(0.5);
  const Box wall{1.0 + 0.05 * r2, -0.05 * r2, 0.05, 2.0, 135.0};
  const Box box{1.0 + 0.5 * r2 - 0.2 * r2, 0.5 * r2 + 0.2 * r2, 0.5, 0.2, 45.0};
  EXPECT_NEAR(RangeTo(box, -0.5, -0.2), 1.0, 1e-5);
  const msgs::RangeReading alone = Read({box});  // without the wall, C is a free edge
  ASSERT_TRUE(alone.echo);
  EXPECT_NEAR(alone.range_m, 1.0, 1e-5);
  EXPECT_FALSE(Read({wall, box}).echo);
}

TEST(SonarSensorTest, NoiseIsOnePercentOfRangeAndZeroMean) {
  Scene scene(RobotIn("p3dx", FloorWorld("sonar_noise"), {0.2, 0.1, 10.0 * kDeg}));
  // A 4 x 3 m box around the robot.
  const SegmentCaster caster(RoomSegments({-1.8, 2.2, -1.4, 1.6}));
  SonarOptions options;
  SonarOptions exact = options;
  exact.noise_free = true;
  SonarSensor noisy(scene, SonarSensor::DefaultSiteNames(), options, 9);
  SonarSensor clean(scene, SonarSensor::DefaultSiteNames(), exact, 1);
  const msgs::RangeRing truth = clean.Measure(scene, caster);
  SampleStats stats;
  while (stats.count() < 20000) {
    const msgs::RangeRing ring = noisy.Measure(scene, caster);
    ASSERT_EQ(ring.readings.size(), 16u);
    for (std::size_t k = 0; k < 16; ++k) {
      if (!truth.readings[k].echo) continue;
      ASSERT_TRUE(ring.readings[k].echo);
      const double z = (ring.readings[k].range_m - truth.readings[k].range_m) /
                       (0.01 * truth.readings[k].range_m);
      stats.Add(z);
    }
  }
  const double mean = stats.Mean(), sigma = stats.Sigma();
  EXPECT_LT(std::abs(mean), 0.05);
  EXPECT_NEAR(sigma, 1.0, 0.05);
}

TEST(SonarSensorTest, MissingSiteIsAConfigErrorNamingTheSite) {
  Scene scene(RobotIn("p3dx", FloorWorld("sonar_missing"), {}));
  try {
    SonarSensor sonar(scene, {"sonar_0", "sonar_16"}, SonarOptions{}, 1);
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("sonar_16"), std::string::npos) << e.what();
  }
}

TEST(SonarOptionsTest, ValidateNamesTheField) {
  EXPECT_NO_THROW(SonarOptions{}.Validate());
  ExpectInvalidField(SonarOptions{.beam_half_angle_deg = 95.0}, "beam_half_angle_deg");
  ExpectInvalidField(SonarOptions{.rays_per_cone = 0}, "rays_per_cone");
  ExpectInvalidField(SonarOptions{.incidence_limit_deg = -1.0}, "incidence_limit_deg");
  ExpectInvalidField(SonarOptions{.range_min_m = 6.0}, "range_min_m");
  ExpectInvalidField(SonarOptions{.range_max_m = 0.0}, "range_max_m");
  ExpectInvalidField(SonarOptions{.range_noise_fraction = -0.01}, "range_noise_fraction");
  ExpectInvalidField(SonarOptions{.rate_hz = 0.0}, "rate_hz");
  ExpectInvalidField(SonarOptions{.edge_echo_range_m = 0.0}, "edge_echo_range_m");
  ExpectInvalidField(SonarOptions{.edge_echo_range_m = std::nan("")}, "edge_echo_range_m");
}

// Casts each single ray (the bounce and foot rays) as far as `far_m`, whatever range it is asked
// for; batches as asked. Beyond the ranges the sensor used to ask for (range_max_m for the foot
// ray, 2 range_max_m - d1 for a bounce) a hit changes no reading: a foot beyond range_max_m is
// ignored, a bounce of length d2 makes a path of at least d2 > range_max_m.
class FarCaster : public RayCaster {
 public:
  FarCaster(const RayCaster& inner, double far_m) : inner_(inner), far_m_(far_m) {}
  bool Cast(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W, double,
            RayHit* hit) const override {
    return inner_.Cast(origin_W, dir_W, far_m_, hit);
  }
  void CastBatch(const Eigen::Vector3d* origins_W, const Eigen::Vector3d* dirs_W, int count,
                 double max_range_m, bool with_normal, RayHit* hits, bool* found) const override {
    inner_.CastBatch(origins_W, dirs_W, count, max_range_m, with_normal, hits, found);
  }

 private:
  const RayCaster& inner_;
  double far_m_;
};

// The sensor bounds its bounce and foot rays by the nearest echo so far (and range_max_m): a hit
// beyond cannot change the reading. Random walls about the whole ring, corner echoes and multipath
// on and off: every reading equals the one cast without the bounds (bit for bit).
TEST(SonarSensorTest, BoundedBounceAndFootRaysGiveTheReadingsOfUnboundedOnes) {
  const Scene scene(RobotIn("p3dx", FloorWorld("sonar_bounded_rays"), {0.2, -0.1, 10.0 * kDeg}));
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int echoes = 0, readings = 0, differing_from_direct = 0;
  for (int trial = 0; trial < 600; ++trial) {
    std::vector<Segment> walls;
    const int count = 1 + static_cast<int>(unit(rng) * 6);
    for (int k = 0; k < count; ++k) {
      const double bearing = 2.0 * std::numbers::pi * unit(rng), dist = 0.4 + 5.0 * unit(rng);
      const double cx = 0.2 + dist * std::cos(bearing), cy = -0.1 + dist * std::sin(bearing);
      const double along = std::numbers::pi * unit(rng), half = 0.2 + 3.0 * unit(rng);
      walls.push_back({Eigen::Vector2d(cx - half * std::cos(along), cy - half * std::sin(along)),
                       Eigen::Vector2d(cx + half * std::cos(along), cy + half * std::sin(along)),
                       k + 1});
    }
    const SegmentCaster caster(walls);
    SonarOptions options;
    options.noise_free = true;
    options.multipath = trial % 3 == 0;
    options.corner_echoes = trial % 5 != 0;
    options.incidence_limit_deg = trial % 2 == 0 ? 20.0 : 8.0;
    SonarSensor bounded(scene, SonarSensor::DefaultSiteNames(), options, 1);
    SonarSensor unbounded(scene, SonarSensor::DefaultSiteNames(), options, 1);
    const msgs::RangeRing a = bounded.Measure(scene, caster);
    const msgs::RangeRing b =
        unbounded.Measure(scene, FarCaster(caster, 2.0 * options.range_max_m));
    SonarOptions direct_only = options;
    direct_only.corner_echoes = false;
    direct_only.multipath = false;
    SonarSensor direct(scene, SonarSensor::DefaultSiteNames(), direct_only, 1);
    const msgs::RangeRing c = direct.Measure(scene, caster);
    for (std::size_t k = 0; k < a.readings.size(); ++k) {
      ++readings;
      ASSERT_EQ(a.readings[k].echo, b.readings[k].echo) << "trial " << trial << " sonar " << k;
      ASSERT_EQ(a.readings[k].range_m, b.readings[k].range_m)
          << "trial " << trial << " sonar " << k;
      echoes += a.readings[k].echo;
      differing_from_direct += a.readings[k].echo != c.readings[k].echo ||
                               a.readings[k].range_m != c.readings[k].range_m;
    }
  }
  // The cases are not all direct echoes: bounces set (or fail to set) a good share of them.
  EXPECT_GT(echoes, readings / 4);
  EXPECT_GT(differing_from_direct, readings / 40);
}

// The same in the shipped office (tables' legs and tops, boxes, walls) through both real casters,
// the robot at random poses, with edge echoes, multipath and corner echoes on and off: the
// bounded bounce and foot rays give the readings of unbounded ones, bit for bit (s66 review).
TEST(SonarSensorSceneTest, BoundedRaysGiveTheReadingsOfUnboundedOnesThroughTheRealCasters) {
  std::mt19937_64 rng(66);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int echoes = 0, readings = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const msgs::Pose2D spawn{-4.0 + 8.0 * unit(rng), -3.0 + 6.0 * unit(rng),
                             2.0 * std::numbers::pi * unit(rng)};
    const Scene scene(RobotIn("p3dx", SourceRoot() / "worlds" / "office.xml", spawn));
    const MujocoRayCaster mujoco(scene.model(), scene.data());
    const GridRayCaster2D grid(scene.model(), scene.data());
    for (int config = 0; config < 8; ++config) {
      SonarOptions options;
      options.noise_free = true;
      options.multipath = config & 1;
      options.corner_echoes = config & 2;
      options.edge_echoes = config & 4;
      options.incidence_limit_deg = trial % 2 == 0 ? 20.0 : 8.0;
      for (const RayCaster* caster :
           {static_cast<const RayCaster*>(&mujoco), static_cast<const RayCaster*>(&grid)}) {
        SonarSensor bounded(scene, SonarSensor::DefaultSiteNames(), options, 1);
        SonarSensor unbounded(scene, SonarSensor::DefaultSiteNames(), options, 1);
        const msgs::RangeRing a = bounded.Measure(scene, *caster);
        const msgs::RangeRing b =
            unbounded.Measure(scene, FarCaster(*caster, 2.0 * options.range_max_m));
        for (std::size_t k = 0; k < a.readings.size(); ++k) {
          ++readings;
          ASSERT_EQ(a.readings[k].echo, b.readings[k].echo) << trial << " " << config << " " << k;
          ASSERT_EQ(a.readings[k].range_m, b.readings[k].range_m)
              << trial << " " << config << " " << k;
          echoes += a.readings[k].echo;
        }
      }
    }
  }
  EXPECT_GT(echoes, readings / 4);
}

// The P3-DX in a real MuJoCo room: interior [-2, 3] x [-1.5, 2.5], optionally rotated.
TEST(SonarSensorSceneTest, SideSonarsReadTheWallsTheyFaceInAxisAlignedAndRotatedRooms) {
  for (const double yaw_deg : {0.0, 30.0}) {
    const double yaw = yaw_deg * kDeg;
    const auto world = RoomWorld("sonar_room_" + std::to_string(int(yaw_deg)),
                                 Rectangle{-2.0, 3.0, -1.5, 2.5}, yaw);
    const msgs::Pose2D X_room_R{0.3, 0.4, 0.0};
    const Scene scene(RobotIn("p3dx", world, msgs::Pose2D{0.0, 0.0, yaw} * X_room_R));
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
