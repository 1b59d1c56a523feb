#include "sim/raycast/grid_ray_caster_2d.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "plywood_paths.h"
#include "sim/raycast/mujoco_ray_caster.h"
#include "sim/world/mujoco_handles.h"
#include "tests/support/ray_caster_test_support.h"

namespace plywood::sim {
namespace {

using plywood::testing::CompiledWorld;
using plywood::testing::ExpectNormal;

CompiledWorld Compile(const std::string& xml) {
  return plywood::testing::CompileWorld(xml, "grid_ray_world.xml");
}

TEST(GridRayCaster2DTest, OptionsValidate) {
  GridRayCaster2DOptions options;
  EXPECT_NO_THROW(options.Validate());
  options.cell_size_m = -1;
  try {
    options.Validate();
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("cell_size_m:", 0), 0u) << e.what();
  }
  options = GridRayCaster2DOptions();
  options.max_cells = 0;
  EXPECT_THROW(options.Validate(), std::invalid_argument);
  for (const double tolerance : {-1e-3, 0.02, std::nan("")}) {
    options = GridRayCaster2DOptions();
    options.level_tolerance_rad = tolerance;
    EXPECT_THROW(options.Validate(), std::invalid_argument) << tolerance;
  }
}

TEST(GridRayCaster2DTest, StaticWorldNeedsNoMujocoCallsForHorizontalRays) {
  const CompiledWorld w = Compile(plywood::testing::ClosedFormWorld());
  const GridRayCaster2D grid(w.model.get(), w.data.get());
  EXPECT_EQ(grid.num_grid_geoms(), 4);  // wall, yawed, post, table top
  EXPECT_EQ(grid.num_horizontal_fallback_geoms(), 0);
  EXPECT_EQ(grid.num_fallback_geoms(), 1);  // the floor, for rays that point down
}

TEST(GridRayCaster2DTest, BoxAtKnownDistanceThroughTheRobot) {
  const CompiledWorld w = Compile(plywood::testing::ClosedFormWorld());
  const GridRayCaster2D grid(w.model.get(), w.data.get());
  RayHit hit;
  ASSERT_TRUE(grid.Cast({0, 0, 0.3}, {1, 0, 0}, 8.0, &hit));
  EXPECT_NEAR(hit.distance_m, 2.95, 1e-12);
  EXPECT_EQ(hit.geom_id, w.Geom("wall"));
  ExpectNormal(hit.normal_W, {-1, 0, 0});
  EXPECT_FALSE(grid.Cast({0, 0, 0.3}, {1, 0, 0}, 2.9, &hit));
  EXPECT_FALSE(grid.Cast({0, 0, 0.3}, {-1, 0, 0}, 100.0, &hit));
  // From outside the grid's rectangle, towards it.
  ASSERT_TRUE(grid.Cast({40, 0.5, 1.9}, {-1, 0, 0}, 100.0, &hit));
  EXPECT_NEAR(hit.distance_m, 40 - 3.05, 1e-12);
  ExpectNormal(hit.normal_W, {1, 0, 0});
  // Above the wall.
  EXPECT_FALSE(grid.Cast({40, 0.5, 2.1}, {-1, 0, 0}, 100.0, &hit));
}

TEST(GridRayCaster2DTest, YawedBoxObliqueRay) {
  const CompiledWorld w = Compile(plywood::testing::ClosedFormWorld());
  const GridRayCaster2D grid(w.model.get(), w.data.get());
  const double yaw = M_PI / 6;
  const Eigen::Vector3d u(std::cos(yaw), std::sin(yaw), 0), v(-std::sin(yaw), std::cos(yaw), 0);
  const Eigen::Vector3d target = Eigen::Vector3d(0, -4, 0.3) + 0.5 * u + 0.1 * v;
  const Eigen::Vector3d origin = target + 2.0 * u + 0.7 * v;
  Eigen::Vector3d dir = target - origin;
  dir.z() = 0.0;
  dir.normalize();
  RayHit hit;
  ASSERT_TRUE(grid.Cast(origin, dir, 8.0, &hit));
  EXPECT_NEAR(hit.distance_m, std::hypot(2.0, 0.7), 1e-12);
  EXPECT_EQ(hit.geom_id, w.Geom("yawed"));
  ExpectNormal(hit.normal_W, u);
}

TEST(GridRayCaster2DTest, CylinderOffAxis) {
  const CompiledWorld w = Compile(plywood::testing::ClosedFormWorld());
  const GridRayCaster2D grid(w.model.get(), w.data.get());
  RayHit hit;
  ASSERT_TRUE(grid.Cast({-1, 1.1, 0.3}, {-1, 0, 0}, 8.0, &hit));
  const double depth = std::sqrt(0.25 * 0.25 - 0.1 * 0.1);
  EXPECT_NEAR(hit.distance_m, 2.0 - depth, 1e-12);
  EXPECT_EQ(hit.geom_id, w.Geom("post"));
  ExpectNormal(hit.normal_W, Eigen::Vector3d(depth, 0.1, 0) / 0.25);
}

TEST(GridRayCaster2DTest, TableTopAboveRayHeightIsNotHit) {
  const CompiledWorld w = Compile(plywood::testing::ClosedFormWorld());
  const GridRayCaster2D grid(w.model.get(), w.data.get());
  RayHit hit;
  EXPECT_FALSE(grid.Cast({0, 2, 0.3}, {0, 1, 0}, 8.0, &hit));
  ASSERT_TRUE(grid.Cast({0, 2, 0.72}, {0, 1, 0}, 8.0, &hit));
  EXPECT_NEAR(hit.distance_m, 1.6, 1e-12);
  EXPECT_EQ(hit.geom_id, w.Geom("table_top"));
  ExpectNormal(hit.normal_W, {0, -1, 0});
}

TEST(GridRayCaster2DTest, DownwardRayHitsTheFloor) {
  const CompiledWorld w = Compile(plywood::testing::ClosedFormWorld());
  const GridRayCaster2D grid(w.model.get(), w.data.get());
  RayHit hit;
  ASSERT_TRUE(grid.Cast({0, 0, 0.3}, Eigen::Vector3d(-1, 0, -1).normalized(), 8.0, &hit));
  EXPECT_NEAR(hit.distance_m, 0.3 * std::sqrt(2.0), 1e-12);
  EXPECT_EQ(hit.geom_id, w.Geom("floor"));
  ExpectNormal(hit.normal_W, {0, 0, 1});
}

// A room of about 60 random boxes and cylinders on the floor, floating (table tops, shelves),
// yawed at random, plus the awkward cases: tilted geoms, a static body with its own pose, round
// geoms, a moving box, a robot in group 3 and a transparent geom.
std::string RandomWorld(uint64_t seed, int geoms) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(-9.5, 9.5), uy(-6.5, 6.5), unit(0.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 9);
  std::ostringstream xml;
  xml.precision(17);
  xml << "<mujoco><worldbody>\n<geom name='floor' type='plane' size='0 0 1'/>\n"
      << "<geom type='box' pos='0 7 1.25' size='10 0.05 1.25'/>\n"
      << "<geom type='box' pos='0 -7 1.25' size='10 0.05 1.25'/>\n"
      << "<geom type='box' pos='10 0 1.25' size='0.05 7 1.25'/>\n"
      << "<geom type='box' pos='-10 0 1.25' size='0.05 7 1.25'/>\n";
  for (int i = 0; i < geoms; ++i) {
    const double x = ux(rng), y = uy(rng);
    // Half the yaws are multiples of 90 deg, as in real rooms.
    const double yaw = unit(rng) < 0.5 ? 90.0 * std::floor(4 * unit(rng)) : 360.0 * unit(rng);
    const int k = kind(rng);
    if (k <= 4) {
      const double h = 0.1 + 1.2 * unit(rng);
      xml << "<geom type='box' pos='" << x << " " << y << " " << h << "' euler='0 0 " << yaw
          << "' size='" << 0.02 + 1.2 * unit(rng) << " " << 0.02 + 0.6 * unit(rng) << " " << h
          << "'/>\n";
    } else if (k <= 6) {
      const double h = 0.1 + 0.8 * unit(rng);
      xml << "<geom type='cylinder' pos='" << x << " " << y << " " << h << "' size='"
          << 0.03 + 0.5 * unit(rng) << " " << h << "'/>\n";
    } else if (k == 7) {
      xml << "<geom type='box' pos='" << x << " " << y << " " << 0.7 + 0.1 * unit(rng)
          << "' euler='0 0 " << yaw << "' size='" << 0.3 + 0.6 * unit(rng) << " "
          << 0.3 + 0.4 * unit(rng) << " 0.02'/>\n";
    } else if (k == 8) {
      xml << "<geom type='box' pos='" << x << " " << y << " " << 0.2 + 1.5 * unit(rng)
          << "' euler='0 0 " << yaw << "' size='" << 0.05 + 0.8 * unit(rng) << " "
          << 0.05 + 0.3 * unit(rng) << " " << 0.01 + 0.2 * unit(rng) << "'/>\n";
    } else {
      xml << "<geom type='cylinder' pos='" << x << " " << y << " " << 0.3 + 1.0 * unit(rng)
          << "' size='" << 0.05 + 0.3 * unit(rng) << " " << 0.02 + 0.3 * unit(rng) << "'/>\n";
    }
  }
  xml << "<geom name='tilted' type='box' pos='4 3 0.6' euler='20 10 45' size='0.6 0.2 0.4'/>\n"
      << "<geom name='lying_cylinder' type='cylinder' pos='-4 -3 0.3' euler='90 0 30' "
      << "size='0.3 0.8'/>\n"
      << "<geom type='sphere' pos='6 -4 0.5' size='0.5'/>\n"
      << "<geom type='capsule' pos='-6 4 0.3' euler='0 90 20' size='0.25 0.6'/>\n"
      << "<geom type='ellipsoid' pos='1 -5 0.4' size='0.3 0.5 0.4'/>\n"
      << "<geom name='glass' type='box' rgba='1 1 1 0' pos='0 0 1' size='0.4 0.4 1'/>\n"
      << "<geom type='box' group='4' pos='-1 1 0.5' size='0.2 0.2 0.5'/>\n"
      << "<geom type='box' group='5' pos='1 -1 0.5' size='0.2 0.2 0.5'/>\n"
      << "<body name='shelf' pos='7 5 0' euler='0 0 25'>\n"
      << "  <geom type='box' pos='0.5 0 0.9' size='0.5 0.2 0.9'/>\n"
      << "  <geom type='cylinder' pos='-0.5 0.3 0.4' size='0.1 0.4'/>\n"
      << "</body>\n"
      << "<body name='crate' pos='-7 -5 0.4'><freejoint/>"
      << "<geom name='crate' type='box' size='0.3 0.3 0.3'/></body>\n"
      << "<body name='robot' pos='0 3 0'><freejoint/>"
      << "<geom type='cylinder' group='3' pos='0 0 0.2' size='0.25 0.2'/></body>\n"
      << "</worldbody></mujoco>\n";
  return xml.str();
}

// Casts `rays` rays with both casters and counts disagreements (hit vs miss, geom, distance beyond
// 1e-9 relative, normal beyond 1e-9).
struct Comparison {
  int rays = 0, hits = 0, mismatches = 0;
  std::string first_mismatch;
};

void Compare(const RayCaster& reference, const RayCaster& grid, const Eigen::Vector3d& origin,
             const Eigen::Vector3d& dir, double max_range_m, Comparison* c) {
  RayHit a, b;
  const bool hit_a = reference.Cast(origin, dir, max_range_m, &a);
  const bool hit_b = grid.Cast(origin, dir, max_range_m, &b);
  ++c->rays;
  c->hits += hit_a;
  const bool same =
      hit_a == hit_b &&
      (!hit_a || (a.geom_id == b.geom_id &&
                  std::abs(a.distance_m - b.distance_m) <= 1e-9 * std::max(1.0, a.distance_m) &&
                  (a.normal_W - b.normal_W).norm() <= 1e-9));
  if (!same && c->mismatches++ == 0) {
    std::ostringstream s;
    s.precision(17);
    s << "origin " << origin.transpose() << " dir " << dir.transpose() << ": mj_ray " << hit_a
      << " geom " << a.geom_id << " d " << a.distance_m << " n " << a.normal_W.transpose()
      << "; grid " << hit_b << " geom " << b.geom_id << " d " << b.distance_m << " n "
      << b.normal_W.transpose();
    c->first_mismatch = s.str();
  }
}

class RandomWorldTest : public ::testing::TestWithParam<double> {};

TEST_P(RandomWorldTest, HorizontalRaysMatchMjRayRayForRay) {
  const CompiledWorld w = Compile(RandomWorld(7, 60));
  GridRayCaster2DOptions options;
  options.cell_size_m = GetParam();
  const MujocoRayCaster reference(w.model.get(), w.data.get());
  const GridRayCaster2D grid(w.model.get(), w.data.get(), options);
  EXPECT_GE(grid.num_grid_geoms(), 70);
  // Only the free-moving crate needs MuJoCo on every horizontal ray.
  EXPECT_EQ(grid.num_horizontal_fallback_geoms(), 1);

  std::mt19937_64 rng(11);
  // Some origins lie outside the room and the grid, some inside geoms.
  std::uniform_real_distribution<double> ux(-12, 12), uy(-9, 9), uz(0.01, 2.6), yaw(-M_PI, M_PI);
  Comparison c;
  for (int i = 0; i < 10000; ++i) {
    const double a = yaw(rng);
    const Eigen::Vector3d origin(ux(rng), uy(rng), i % 4 == 0 ? 0.3 : uz(rng));
    Compare(reference, grid, origin, {std::cos(a), std::sin(a), 0.0}, i % 2 ? 8.0 : 30.0, &c);
  }
  EXPECT_EQ(c.mismatches, 0) << c.first_mismatch;
  EXPECT_GT(c.hits, 6000);  // the rays do meet geometry
}

TEST_P(RandomWorldTest, TiltedAndSteepRaysMatchMjRay) {
  const CompiledWorld w = Compile(RandomWorld(8, 60));
  GridRayCaster2DOptions options;
  options.cell_size_m = GetParam();
  options.level_tolerance_rad = 0.0;  // every ray exactly as given
  const MujocoRayCaster reference(w.model.get(), w.data.get());
  const GridRayCaster2D grid(w.model.get(), w.data.get(), options);
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> ux(-12, 12), uy(-9, 9), uz(0.01, 2.6), yaw(-M_PI, M_PI),
      pitch(-M_PI / 2, M_PI / 2);
  std::normal_distribution<double> tilt(0.0, 1e-3);
  Comparison c;
  for (int i = 0; i < 4000; ++i) {
    const double a = yaw(rng);
    // Even rays: a robot tilted by a few mrad on a bumpy floor; odd rays: anywhere in 3-D.
    const double p = i % 2 ? pitch(rng) : tilt(rng);
    const Eigen::Vector3d dir(std::cos(p) * std::cos(a), std::cos(p) * std::sin(a), std::sin(p));
    Compare(reference, grid, {ux(rng), uy(rng), uz(rng)}, dir, 8.0, &c);
  }
  Compare(reference, grid, {1, 1, 2}, {0, 0, -1}, 8.0, &c);  // straight down
  EXPECT_EQ(c.mismatches, 0) << c.first_mismatch;
}

TEST_P(RandomWorldTest, NearlyLevelRaysAreCastLevel) {
  const CompiledWorld w = Compile(RandomWorld(8, 60));
  GridRayCaster2DOptions options;
  options.cell_size_m = GetParam();
  EXPECT_EQ(options.level_tolerance_rad, 1e-3);  // the default
  const MujocoRayCaster reference(w.model.get(), w.data.get());
  const GridRayCaster2D grid(w.model.get(), w.data.get(), options);
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> ux(-12, 12), uy(-9, 9), uz(0.01, 2.6), yaw(-M_PI, M_PI),
      tilt(-0.99e-3, 0.99e-3);
  int hits = 0, same = 0, close = 0;
  for (int i = 0; i < 4000; ++i) {
    const double a = yaw(rng), p = tilt(rng);
    const Eigen::Vector3d origin(ux(rng), uy(rng), uz(rng));
    const Eigen::Vector3d dir(std::cos(p) * std::cos(a), std::cos(p) * std::sin(a), std::sin(p));
    const Eigen::Vector3d level_dir = Eigen::Vector3d(dir.x(), dir.y(), 0.0).normalized();
    // Bit for bit what mj_ray gives for the level ray from the same origin ...
    RayHit tilted_hit, level_hit;
    const bool hit = grid.Cast(origin, dir, 8.0, &tilted_hit);
    ASSERT_EQ(hit, reference.Cast(origin, level_dir, 8.0, &level_hit)) << i;
    if (!hit) continue;
    ++hits;
    same +=
        tilted_hit.distance_m == level_hit.distance_m && tilted_hit.geom_id == level_hit.geom_id;
    // ... and, on the vertical faces of upright walls, what the tilted ray meets within 1 - cos.
    RayHit exact;
    if (reference.Cast(origin, dir, 8.0, &exact) && exact.geom_id == level_hit.geom_id &&
        std::abs(level_hit.normal_W.z()) < 1e-12) {
      close += std::abs(exact.distance_m * std::cos(p) - level_hit.distance_m) < 1e-9;
    }
  }
  EXPECT_EQ(same, hits);
  EXPECT_GT(hits, 1500);
  EXPECT_GT(close, hits / 2);
}

TEST_P(RandomWorldTest, CastWithoutNormalGivesCastsDistanceAndGeom) {
  const CompiledWorld w = Compile(RandomWorld(9, 60));
  GridRayCaster2DOptions options;
  options.cell_size_m = GetParam();
  const MujocoRayCaster reference(w.model.get(), w.data.get());
  const GridRayCaster2D grid(w.model.get(), w.data.get(), options);
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> ux(-12, 12), uy(-9, 9), uz(0.01, 2.6), yaw(-M_PI, M_PI),
      pitch(-M_PI / 2, M_PI / 2);
  std::normal_distribution<double> tilt(0.0, 1e-3);
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    const double a = yaw(rng);
    // Level, slightly tilted (the 2-D path's tolerance) and anywhere in 3-D.
    const double p = i % 3 == 0 ? 0.0 : i % 3 == 1 ? tilt(rng) : pitch(rng);
    const Eigen::Vector3d origin(ux(rng), uy(rng), uz(rng));
    const Eigen::Vector3d dir(std::cos(p) * std::cos(a), std::cos(p) * std::sin(a), std::sin(p));
    for (const RayCaster* caster :
         {static_cast<const RayCaster*>(&reference), static_cast<const RayCaster*>(&grid)}) {
      RayHit full, bare;
      const Eigen::Vector3d untouched(7.0, 8.0, 9.0);
      bare.normal_W = untouched;
      const bool hit = caster->Cast(origin, dir, 8.0, &full);
      ASSERT_EQ(caster->CastWithoutNormal(origin, dir, 8.0, &bare), hit) << i;
      if (!hit) continue;
      ++hits;
      EXPECT_EQ(bare.distance_m, full.distance_m) << i;
      EXPECT_EQ(bare.geom_id, full.geom_id) << i;
      EXPECT_EQ(bare.normal_W, untouched) << i;  // left as it was
    }
  }
  EXPECT_GT(hits, 2000);
}

// A scan's beams from one origin: the batch and the fan give, beam by beam, the very bits
// CastWithoutNormal gives (level beams, beams within the levelling tolerance and beams beyond it),
// and for level beams what mj_ray gives. Origins anywhere: outside the grid, inside and beside
// geoms, on corners.
TEST_P(RandomWorldTest, ScanBatchGivesCastWithoutNormalsBitsBeamForBeam) {
  for (const uint64_t world_seed : {21u, 22u}) {
    const CompiledWorld w = Compile(RandomWorld(world_seed, world_seed == 21u ? 60 : 150));
    GridRayCaster2DOptions options;
    options.cell_size_m = GetParam();
    const MujocoRayCaster reference(w.model.get(), w.data.get());
    const GridRayCaster2D grid(w.model.get(), w.data.get(), options);
    std::mt19937_64 rng(world_seed);
    std::uniform_real_distribution<double> ux(-12, 12), uy(-9, 9), uz(0.01, 2.6), yaw(-M_PI, M_PI),
        unit(0.0, 1.0);
    std::normal_distribution<double> jitter(0.0, 6e-4);
    std::vector<Eigen::Vector3d> dirs;
    std::vector<RayHit> hits;
    int beams = 0, hit_count = 0, level_beams = 0, mj_checked = 0;
    for (int scan = 0; scan < 240; ++scan) {
      Eigen::Vector3d origin(ux(rng), uy(rng), scan % 3 == 0 ? 0.3 : uz(rng));
      if (scan % 8 == 1) {
        // Exactly on, or a hair beside, a corner of some geom's footprint.
        const int g = std::uniform_int_distribution<int>(1, 4)(rng);
        const double* p = w.data->geom_xpos + 3 * g;
        const double* size = w.model->geom_size + 3 * g;
        const double eps = scan % 16 == 1 ? 0.0 : 1e-4 * (unit(rng) - 0.5);
        origin = {p[0] + size[0] + eps, p[1] + size[1] - eps, p[2]};
      }
      const double heading = yaw(rng);
      // Level scans, scans tilted within the levelling tolerance, and scans tilted beyond it.
      const int kind = scan % 3;
      const double pitch = kind == 0 ? 0.0 : kind == 1 ? jitter(rng) : 0.02 * (unit(rng) - 0.5);
      const double roll = kind == 0 ? 0.0 : kind == 1 ? jitter(rng) : 0.02 * (unit(rng) - 0.5);
      const Eigen::Matrix3d R = (Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                                    .toRotationMatrix();
      const int n = scan % 5 == 0 ? 1 + static_cast<int>(unit(rng) * 40) : 361;
      const double fov = scan % 4 == 0 ? 2 * M_PI : M_PI;
      dirs.resize(n);
      hits.assign(n, RayHit{});
      for (int i = 0; i < n; ++i) {
        const double a = -fov / 2 + fov * i / std::max(1, n - 1);
        dirs[i] = R * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0);
      }
      const double range = scan % 4 == 0 ? 80.0 : scan % 4 == 1 ? 30.0 : 8.0;
      std::unique_ptr<bool[]> found(new bool[n]);
      const std::vector<Eigen::Vector3d> origins(n, origin);
      grid.CastBatch(origins.data(), dirs.data(), n, range, /*with_normal=*/false, hits.data(),
                     found.get());
      std::vector<RayHit> fan_hits(n);
      std::unique_ptr<bool[]> fan_found(new bool[n]);
      grid.CastFanWithoutNormal(origin, dirs.data(), n, range, fan_hits.data(), fan_found.get());
      for (int i = 0; i < n; ++i) {
        RayHit one;
        const bool hit = grid.CastWithoutNormal(origin, dirs[i], range, &one);
        ++beams;
        ASSERT_EQ(fan_found[i], hit) << "scan " << scan << " beam " << i;
        if (hit) {
          ASSERT_EQ(fan_hits[i].distance_m, one.distance_m) << "scan " << scan << " beam " << i;
          ASSERT_EQ(fan_hits[i].geom_id, one.geom_id) << "scan " << scan << " beam " << i;
        }
        ASSERT_EQ(found[i], hit) << "scan " << scan << " beam " << i;
        if (!hit) continue;
        ++hit_count;
        ASSERT_EQ(hits[i].distance_m, one.distance_m) << "scan " << scan << " beam " << i;
        ASSERT_EQ(hits[i].geom_id, one.geom_id) << "scan " << scan << " beam " << i;
        if (dirs[i].z() == 0.0) {
          ++level_beams;
          RayHit exact;
          ASSERT_TRUE(reference.CastWithoutNormal(origin, dirs[i], range, &exact));
          ASSERT_EQ(exact.geom_id, one.geom_id);
          ASSERT_NEAR(exact.distance_m, one.distance_m, 1e-9 * std::max(1.0, one.distance_m));
          ++mj_checked;
        }
      }
    }
    EXPECT_GT(beams, 60000);
    EXPECT_GT(hit_count, beams / 2);
    EXPECT_GT(level_beams, 10000);
    EXPECT_EQ(mj_checked, level_beams);
  }
}

// CastBatch with normals gives, ray by ray, the very bits Cast gives: whether it hits, and the
// distance, geom and normal. Counts the rays and the hits; `where` names the batch in a failure.
void ExpectBatchIsCast(const GridRayCaster2D& grid, const std::vector<Eigen::Vector3d>& origins,
                       const std::vector<Eigen::Vector3d>& dirs, double range,
                       const std::string& where, int* rays, int* hit_count) {
  const int n = static_cast<int>(dirs.size());
  std::vector<RayHit> hits(n);
  std::unique_ptr<bool[]> found(new bool[n]);
  grid.CastBatch(origins.data(), dirs.data(), n, range, /*with_normal=*/true, hits.data(),
                 found.get());
  for (int i = 0; i < n; ++i) {
    RayHit one;
    const bool hit = grid.Cast(origins[i], dirs[i], range, &one);
    ++*rays;
    ASSERT_EQ(found[i], hit) << where << " ray " << i;
    if (!hit) continue;
    ++*hit_count;
    ASSERT_EQ(hits[i].distance_m, one.distance_m) << where << " ray " << i;
    ASSERT_EQ(hits[i].geom_id, one.geom_id) << where << " ray " << i;
    ASSERT_EQ(hits[i].normal_W, one.normal_W) << where << " ray " << i;
  }
}

// A sonar ring's cones: rays from origins up to 0.3 m apart, with normals. The batch gives, ray by
// ray, the very bits Cast gives (distance, geom and normal).
TEST_P(RandomWorldTest, RingBatchGivesCastsBitsRayForRay) {
  const CompiledWorld w = Compile(RandomWorld(24, 120));
  GridRayCaster2DOptions options;
  options.cell_size_m = GetParam();
  const GridRayCaster2D grid(w.model.get(), w.data.get(), options);
  std::mt19937_64 rng(24);
  std::uniform_real_distribution<double> ux(-12, 12), uy(-9, 9), uz(0.05, 1.5), yaw(-M_PI, M_PI),
      unit(0.0, 1.0);
  std::normal_distribution<double> jitter(0.0, 6e-4);
  int rays = 0, hit_count = 0;
  for (int ring = 0; ring < 300; ++ring) {
    const Eigen::Vector3d centre(ux(rng), uy(rng), uz(rng));
    const double ring_radius = ring % 5 == 0 ? 0.0 : 0.3 * unit(rng);
    const double pitch = ring % 3 == 0 ? 0.0 : ring % 3 == 1 ? jitter(rng) : 0.01 * unit(rng);
    std::vector<Eigen::Vector3d> origins, dirs;
    const int sonars = 1 + ring % 16, per_cone = 1 + ring % 9;
    for (int k = 0; k < sonars; ++k) {
      const double a = 2 * M_PI * k / sonars + 0.1 * unit(rng);
      const Eigen::Vector3d site =
          centre + Eigen::Vector3d(ring_radius * std::cos(a), ring_radius * std::sin(a),
                                   ring % 4 == 0 ? 0.01 * unit(rng) : 0.0);
      for (int j = 0; j < per_cone; ++j) {
        const double b = a + 0.26 * (j - per_cone / 2) / std::max(1, per_cone / 2);
        origins.push_back(site);
        dirs.push_back(Eigen::Vector3d(std::cos(pitch) * std::cos(b), std::cos(pitch) * std::sin(b),
                                       std::sin(pitch)));
      }
    }
    ExpectBatchIsCast(grid, origins, dirs, ring % 2 ? 5.0 : 30.0, "ring " + std::to_string(ring),
                      &rays, &hit_count);
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(rays, 8000);
  EXPECT_GT(hit_count, rays / 2);
}

// IntersectShape tries an upright box's near face first and the far one only when it misses: level
// rays must still give mj_ray's distance, geom and normal to the last bit, also from inside boxes,
// along the box axes (one local direction component zero) and grazing faces and corners.
TEST(GridRayCaster2DTest, LevelRaysGiveMjRaysBitsOnUprightBoxes) {
  const CompiledWorld w = Compile(RandomWorld(41, 150));
  const MujocoRayCaster reference(w.model.get(), w.data.get());
  const GridRayCaster2D grid(w.model.get(), w.data.get());
  std::vector<int> boxes;
  for (int g = 0; g < w.model->ngeom; ++g) {
    const double* R = w.data->geom_xmat + 9 * g;
    if (w.model->geom_type[g] == mjGEOM_BOX && R[2] == 0 && R[5] == 0 && R[8] > 0.99 &&
        IsRayVisibleGeom(w.model.get(), g)) {
      boxes.push_back(g);
    }
  }
  ASSERT_GT(boxes.size(), 60u);
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
  int rays = 0, hits = 0, inside = 0;
  for (int i = 0; i < 20000; ++i) {
    // A point about a random box (inside it for a quarter), aimed at a corner, along an axis of
    // the box or anywhere.
    const int g = boxes[rng() % boxes.size()];
    const double* p = w.data->geom_xpos + 3 * g;
    const double* R = w.data->geom_xmat + 9 * g;
    const double* size = w.model->geom_size + 3 * g;
    const bool in_box = i % 4 == 0;
    const double lx = in_box ? size[0] * sym(rng) : 3.0 * sym(rng);
    const double ly = in_box ? size[1] * sym(rng) : 3.0 * sym(rng);
    const Eigen::Vector3d origin(p[0] + R[0] * lx + R[1] * ly, p[1] + R[3] * lx + R[4] * ly,
                                 p[2] + size[2] * 0.9 * sym(rng));
    Eigen::Vector3d dir;
    if (i % 3 == 0) {
      const double cx = (rng() % 2 ? 1 : -1) * size[0], cy = (rng() % 2 ? 1 : -1) * size[1];
      dir = Eigen::Vector3d(p[0] + R[0] * cx + R[1] * cy - origin.x(),
                            p[1] + R[3] * cx + R[4] * cy - origin.y(), 0.0);
    } else if (i % 3 == 1) {
      const int axis = static_cast<int>(rng() % 2);
      const double sign = rng() % 2 ? 1.0 : -1.0;
      dir = Eigen::Vector3d(sign * R[axis], sign * R[3 + axis], 0.0);
    } else {
      const double a = 2 * M_PI * unit(rng);
      dir = Eigen::Vector3d(std::cos(a), std::sin(a), 0.0);
    }
    if (dir.squaredNorm() == 0) continue;
    dir.normalize();
    RayHit a, b;
    const bool hit = reference.Cast(origin, dir, 30.0, &a);
    ++rays;
    ASSERT_EQ(grid.Cast(origin, dir, 30.0, &b), hit) << i;
    if (!hit) continue;
    ++hits;
    inside += in_box && a.geom_id == g;
    ASSERT_EQ(a.distance_m, b.distance_m) << i;
    ASSERT_EQ(a.geom_id, b.geom_id) << i;
    ASSERT_EQ(a.normal_W, b.normal_W) << i;
  }
  EXPECT_GT(hits, rays / 2);
  EXPECT_GT(inside, 1000);  // rays leaving a box through its far face
}

// A ring whose origins spread as far as the shapes around it lie (a footprint between r and 2 r
// from the centre, where the angular intervals are widened most), with rays aimed exactly at
// footprint corners, just beside them and anywhere: CastBatch gives Cast's bits ray for ray.
TEST(GridRayCaster2DTest, WideRingBatchNearShapesGivesCastsBits) {
  const CompiledWorld w = Compile(RandomWorld(42, 150));
  std::vector<int> boxes;
  for (int g = 0; g < w.model->ngeom; ++g) {
    const double* R = w.data->geom_xmat + 9 * g;
    if (w.model->geom_type[g] == mjGEOM_BOX && R[2] == 0 && R[5] == 0 &&
        IsRayVisibleGeom(w.model.get(), g)) {
      boxes.push_back(g);
    }
  }
  ASSERT_GT(boxes.size(), 60u);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
  int rays = 0, hit_count = 0;
  for (const double cell : {0.13, 0.5, 2.0}) {
    GridRayCaster2DOptions options;
    options.cell_size_m = cell;
    const GridRayCaster2D grid(w.model.get(), w.data.get(), options);
    for (int ring = 0; ring < 200; ++ring) {
      const int g = boxes[rng() % boxes.size()];
      const double* p = w.data->geom_xpos + 3 * g;
      const double* R = w.data->geom_xmat + 9 * g;
      const double* size = w.model->geom_size + 3 * g;
      // The centre 0.05-2 m outside the box's footprint, the ring's radius 0.4-1.0 of that gap.
      const double gap = 0.05 + 1.95 * unit(rng), a0 = 2 * M_PI * unit(rng);
      const double reach = std::hypot(size[0], size[1]) + gap;
      const Eigen::Vector3d centre(p[0] + reach * std::cos(a0), p[1] + reach * std::sin(a0),
                                   p[2] + 0.5 * size[2] * sym(rng));
      const double ring_radius = gap * (0.4 + 0.6 * unit(rng));
      std::vector<Eigen::Vector3d> origins, dirs;
      const int sonars = 2 + ring % 15;
      for (int k = 0; k < sonars; ++k) {
        const double a = 2 * M_PI * k / sonars;
        const Eigen::Vector3d site =
            centre + ring_radius * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0);
        for (int corner = 0; corner < 4; ++corner) {
          const double cx = (corner & 1 ? 1 : -1) * size[0], cy = (corner & 2 ? 1 : -1) * size[1];
          const Eigen::Vector2d to(p[0] + R[0] * cx + R[1] * cy - site.x(),
                                   p[1] + R[3] * cx + R[4] * cy - site.y());
          const double b = std::atan2(to.y(), to.x());
          for (const double nudge : {0.0, 1e-12, -1e-12, 1e-7, -1e-7}) {
            origins.push_back(site);
            dirs.emplace_back(std::cos(b + nudge), std::sin(b + nudge), 0.0);
          }
        }
        for (int j = 0; j < 5; ++j) {
          const double b = a + 0.26 * (j - 2) / 2 + (ring % 2 ? M_PI : 0.0);
          origins.push_back(site);
          dirs.emplace_back(std::cos(b), std::sin(b), 0.0);
        }
      }
      ExpectBatchIsCast(grid, origins, dirs, ring % 3 == 0 ? 30.0 : 5.0,
                        "cell " + std::to_string(cell) + " ring " + std::to_string(ring), &rays,
                        &hit_count);
      if (HasFatalFailure()) return;
    }
  }
  EXPECT_GT(rays, 50000);
  EXPECT_GT(hit_count, rays / 2);
}

// The base class's batch (MujocoRayCaster's) is CastWithoutNormal beam by beam.
TEST(GridRayCaster2DTest, DefaultBatchIsCastWithoutNormal) {
  const CompiledWorld w = Compile(RandomWorld(23, 40));
  const MujocoRayCaster reference(w.model.get(), w.data.get());
  std::vector<Eigen::Vector3d> dirs;
  for (int i = 0; i < 90; ++i) {
    const double a = i * 2 * M_PI / 90;
    dirs.emplace_back(std::cos(a), std::sin(a), i % 3 == 0 ? 0.0 : 0.01 * (i % 7 - 3));
    dirs.back().normalize();
  }
  std::vector<RayHit> hits(dirs.size());
  std::unique_ptr<bool[]> found(new bool[dirs.size()]);
  const Eigen::Vector3d origin(0.5, -1.5, 0.4);
  const std::vector<Eigen::Vector3d> origins(dirs.size(), origin);
  reference.CastBatch(origins.data(), dirs.data(), static_cast<int>(dirs.size()), 8.0,
                      /*with_normal=*/false, hits.data(), found.get());
  int hit_count = 0;
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    RayHit one;
    ASSERT_EQ(found[i], reference.CastWithoutNormal(origin, dirs[i], 8.0, &one)) << i;
    if (!found[i]) continue;
    ++hit_count;
    EXPECT_EQ(hits[i].distance_m, one.distance_m) << i;
    EXPECT_EQ(hits[i].geom_id, one.geom_id) << i;
  }
  EXPECT_GT(hit_count, 60);
}

INSTANTIATE_TEST_SUITE_P(CellSizes, RandomWorldTest, ::testing::Values(0.13, 0.5, 2.0));

// A building of `rooms_x` x `rooms_y` rooms (8 x 6 m, walls with door gaps) with random boxes and
// cylinders in each: most rays end at a wall within a few metres, the rest leave through doors.
std::string RoomsWorld(uint64_t seed, int rooms_x, int rooms_y) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::ostringstream xml;
  xml.precision(17);
  xml << "<mujoco><worldbody>\n<geom name='floor' type='plane' size='0 0 1'/>\n";
  const auto wall = [&](double x0, double y0, double x1, double y1) {
    xml << "<geom type='box' pos='" << 0.5 * (x0 + x1) << " " << 0.5 * (y0 + y1) << " 0.5' size='"
        << std::max(0.009, 0.5 * std::abs(x1 - x0)) << " "
        << std::max(0.009, 0.5 * std::abs(y1 - y0)) << " 0.5'/>\n";
  };
  for (int i = 0; i <= rooms_x; ++i) {
    for (int j = 0; j < rooms_y; ++j) {  // walls along y, a door in the inner ones
      const double x = 8.0 * i, y0 = 6.0 * j, door = y0 + 1.0 + 3.5 * unit(rng);
      if (i == 0 || i == rooms_x) {
        wall(x, y0, x, y0 + 6.0);
      } else {
        wall(x, y0, x, door);
        wall(x, door + 0.9, x, y0 + 6.0);
      }
    }
  }
  for (int j = 0; j <= rooms_y; ++j) {
    for (int i = 0; i < rooms_x; ++i) {  // walls along x
      const double y = 6.0 * j, x0 = 8.0 * i, door = x0 + 1.0 + 5.5 * unit(rng);
      if (j == 0 || j == rooms_y) {
        wall(x0, y, x0 + 8.0, y);
      } else {
        wall(x0, y, door, y);
        wall(door + 0.9, y, x0 + 8.0, y);
      }
    }
  }
  for (int r = 0; r < rooms_x * rooms_y * 12; ++r) {
    const double x = 8.0 * (r % rooms_x) + 0.5 + 7.0 * unit(rng);
    const double y = 6.0 * ((r / rooms_x) % rooms_y) + 0.5 + 5.0 * unit(rng);
    if (r % 3 == 0) {
      xml << "<geom type='cylinder' pos='" << x << " " << y << " 0.4' size='"
          << 0.02 + 0.2 * unit(rng) << " 0.4'/>\n";
    } else {
      xml << "<geom type='box' pos='" << x << " " << y << " 0.4' euler='0 0 "
          << (r % 2 ? 0.0 : 360.0 * unit(rng)) << "' size='" << 0.05 + 0.4 * unit(rng) << " "
          << 0.05 + 0.3 * unit(rng) << " 0.4'/>\n";
    }
  }
  xml << "</worldbody></mujoco>\n";
  return xml.str();
}

// The batch and the fan collect shapes reach by reach and stop at the walls around the origins;
// in a building of 24 rooms (about 400 shapes) every beam of a scan and every ray of a ring still
// gets the very bits Cast gives, level beams what mj_ray gives, with ranges from short of the
// first reach to beyond the building.
TEST(GridRayCaster2DTest, BatchesInManyRoomsGiveCastsBits) {
  const CompiledWorld w = Compile(RoomsWorld(31, 6, 4));
  ASSERT_GT(w.model->ngeom, 380);
  const MujocoRayCaster reference(w.model.get(), w.data.get());
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> ux(0.2, 47.8), uy(0.2, 23.8), unit(0.0, 1.0);
  int rays = 0, hit_count = 0, far_hits = 0;
  for (const double cell : {0.25, 0.5, 1.0}) {
    GridRayCaster2DOptions options;
    options.cell_size_m = cell;
    const GridRayCaster2D grid(w.model.get(), w.data.get(), options);
    for (int scan = 0; scan < 120; ++scan) {
      const double range = scan % 4 == 0 ? 1.5 : scan % 4 == 1 ? 5.0 : scan % 4 == 2 ? 8.0 : 60.0;
      const bool ring = scan % 2 == 1;
      const Eigen::Vector3d centre(ux(rng), uy(rng), 0.3);
      const double heading = 2 * M_PI * unit(rng);
      const int n = ring ? 16 * 5 : 361;
      std::vector<Eigen::Vector3d> origins(n, centre), dirs(n);
      for (int i = 0; i < n; ++i) {
        const double a = ring ? heading + 2 * M_PI * (i / 5) / 16 + 0.1 * (i % 5 - 2)
                              : heading - M_PI / 2 + M_PI * i / (n - 1);
        dirs[i] = Eigen::Vector3d(std::cos(a), std::sin(a), 0.0);
        if (ring) {
          const double b = heading + 2 * M_PI * (i / 5) / 16;
          origins[i] += 0.25 * Eigen::Vector3d(std::cos(b), std::sin(b), 0.0);
        }
      }
      std::vector<RayHit> hits(n);
      std::unique_ptr<bool[]> found(new bool[n]);
      if (ring) {
        grid.CastBatch(origins.data(), dirs.data(), n, range, /*with_normal=*/true, hits.data(),
                       found.get());
      } else {
        grid.CastFanWithoutNormal(centre, dirs.data(), n, range, hits.data(), found.get());
      }
      for (int i = 0; i < n; ++i) {
        RayHit one, exact;
        const bool hit = ring ? grid.Cast(origins[i], dirs[i], range, &one)
                              : grid.CastWithoutNormal(centre, dirs[i], range, &one);
        ++rays;
        ASSERT_EQ(found[i], hit) << "cell " << cell << " scan " << scan << " ray " << i;
        ASSERT_EQ(reference.CastWithoutNormal(origins[i], dirs[i], range, &exact), hit);
        if (!hit) continue;
        ++hit_count;
        far_hits += one.distance_m > 4.0;
        ASSERT_EQ(hits[i].distance_m, one.distance_m) << "scan " << scan << " ray " << i;
        ASSERT_EQ(hits[i].geom_id, one.geom_id) << "scan " << scan << " ray " << i;
        if (ring) {
          ASSERT_EQ(hits[i].normal_W, one.normal_W) << "scan " << scan << " ray " << i;
        }
        ASSERT_EQ(exact.geom_id, one.geom_id);
        ASSERT_NEAR(exact.distance_m, one.distance_m, 1e-9 * std::max(1.0, one.distance_m));
      }
    }
  }
  EXPECT_GT(rays, 70000);
  EXPECT_GT(hit_count, rays / 2);
  EXPECT_GT(far_hits, rays / 20);  // rays that needed the later reaches
}

TEST(GridRayCaster2DTest, SeesMovingBodiesWhereTheyAreNow) {
  CompiledWorld w = Compile(RandomWorld(9, 20));
  const MujocoRayCaster reference(w.model.get(), w.data.get());
  const GridRayCaster2D grid(w.model.get(), w.data.get());
  // Move the crate into the line of a ray after the grid was built.
  const int crate = mj_name2id(w.model.get(), mjOBJ_BODY, "crate");
  const int qpos = w.model->jnt_qposadr[w.model->body_jntadr[crate]];
  w.data->qpos[qpos] = 0.0;
  w.data->qpos[qpos + 1] = -6.0;
  w.data->qpos[qpos + 2] = 0.3;
  mj_forward(w.model.get(), w.data.get());
  RayHit hit;
  ASSERT_TRUE(grid.Cast({0, -6.0, 0.3}, {0, 0, 1}, 8.0, &hit));
  EXPECT_EQ(hit.geom_id, w.Geom("crate"));
  EXPECT_NEAR(hit.distance_m, 0.3, 1e-12);  // from inside: the exit face, as mj_ray does
  Comparison c;
  for (double a = -M_PI; a < M_PI; a += 0.01) {
    Compare(reference, grid, {0.3, -5.0, 0.3}, {std::cos(a), std::sin(a), 0}, 8.0, &c);
  }
  EXPECT_EQ(c.mismatches, 0) << c.first_mismatch;
}

TEST(GridRayCaster2DTest, OfficeWorldMatchesMjRay) {
  const std::filesystem::path office =
      std::filesystem::path(PLYWOOD_SOURCE_ROOT) / "worlds/office.xml";
  if (!std::filesystem::exists(office)) GTEST_SKIP() << office << " not written yet";
  CompiledWorld w;
  w.model = LoadModelFromFile(office.string());
  w.data.reset(mj_makeData(w.model.get()));
  mj_forward(w.model.get(), w.data.get());
  const MujocoRayCaster reference(w.model.get(), w.data.get());
  const GridRayCaster2D grid(w.model.get(), w.data.get());
  double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9};
  for (int g = 0; g < w.model->ngeom; ++g) {
    if (w.model->geom_type[g] == mjGEOM_PLANE) continue;
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], w.data->geom_xpos[3 * g + k] - w.model->geom_rbound[g]);
      hi[k] = std::max(hi[k], w.data->geom_xpos[3 * g + k] + w.model->geom_rbound[g]);
    }
  }
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> ux(lo[0], hi[0]), uy(lo[1], hi[1]), uz(0.05, 1.0),
      yaw(-M_PI, M_PI);
  Comparison c;
  for (int i = 0; i < 10000; ++i) {
    const double a = yaw(rng);
    const Eigen::Vector3d origin(ux(rng), uy(rng), i % 2 ? 0.3 : uz(rng));
    Compare(reference, grid, origin, {std::cos(a), std::sin(a), 0.0}, 8.0, &c);
  }
  EXPECT_EQ(c.mismatches, 0) << c.first_mismatch;
}

}  // namespace
}  // namespace plywood::sim
