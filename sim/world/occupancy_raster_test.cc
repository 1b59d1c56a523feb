#include "sim/world/occupancy_raster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sim/world/mujoco_handles.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::sim {
namespace {

using Eigen::Vector2d;

MjModelPtr Load(const std::string& xml) {
  return LoadModelFromString(xml, (testing::MakeTempDir("occupancy_raster") / "m.xml").string());
}

UprightGeom Box(const Vector2d& centre, double hx, double hy, double yaw_rad = 0.0) {
  UprightGeom g;
  g.shape = UprightGeom::Shape::kBox;
  g.centre_W = centre;
  g.R_WG = Eigen::Rotation2Dd(yaw_rad).toRotationMatrix();
  g.half_size_xy = {hx, hy};
  g.z_min_m = 0.0;
  g.z_max_m = 1.0;
  return g;
}

UprightGeom Cylinder(const Vector2d& centre, double radius) {
  UprightGeom g;
  g.shape = UprightGeom::Shape::kCylinder;
  g.centre_W = centre;
  g.radius_m = radius;
  g.z_min_m = 0.0;
  g.z_max_m = 1.0;
  return g;
}

OccupancyRasterOptions Options(double resolution_m, int supersamples) {
  OccupancyRasterOptions o;
  o.resolution_m = resolution_m;
  o.supersamples = supersamples;
  o.bounds_W = Eigen::AlignedBox2d(Vector2d(-2.0, -2.0), Vector2d(2.0, 2.0));
  return o;
}

bool OccupiedAt(const OccupancyRaster& r, const Vector2d& p) {
  const auto cell = r.CellAt(p);
  EXPECT_TRUE(cell.has_value()) << p.transpose();
  return cell && r.IsOccupied(cell->x(), cell->y());
}

// A shape's sampled area differs from its true area only in the cells its boundary crosses, a
// band about one sample spacing wide along the perimeter.
void ExpectAreaWithinBound(const std::vector<UprightGeom>& geoms, double true_area,
                           double perimeter) {
  for (const double resolution : {0.1, 0.05, 0.02}) {
    for (const int k : {1, 2, 4}) {
      const OccupancyRaster r = RasteriseOccupancy(geoms, Options(resolution, k));
      const double bound = perimeter * resolution / k;
      EXPECT_NEAR(r.OccupiedAreaM2(), true_area, bound)
          << "resolution " << resolution << " supersamples " << k;
    }
  }
}

TEST(OccupancyRasterTest, AxisAlignedBoxAreaMatches) {
  ExpectAreaWithinBound({Box({0.31, -0.17}, 0.285, 0.4)}, 0.57 * 0.8, 2.0 * (0.57 + 0.8));
}

TEST(OccupancyRasterTest, RotatedBoxAreaMatches) {
  ExpectAreaWithinBound({Box({-0.4, 0.3}, 0.6, 0.2, 0.7)}, 1.2 * 0.4, 2.0 * (1.2 + 0.4));
}

TEST(OccupancyRasterTest, CylinderAreaMatches) {
  const double r = 0.37;
  ExpectAreaWithinBound({Cylinder({0.2, 0.1}, r)}, std::numbers::pi * r * r,
                        2.0 * std::numbers::pi * r);
}

TEST(OccupancyRasterTest, OverlappingGeomsCountOnce) {
  // Two 1 x 1 boxes overlapping by half: the union is 1.5 m^2, their sum 2 m^2.
  const OccupancyRaster r =
      RasteriseOccupancy({Box({0.0, 0.0}, 0.5, 0.5), Box({0.5, 0.0}, 0.5, 0.5)}, Options(0.05, 4));
  EXPECT_NEAR(r.OccupiedAreaM2(), 1.5, 2.0 * (1.5 + 1.0) * 0.05 / 4);
}

TEST(OccupancyRasterTest, GridAlignedBoxIsExact) {
  // Edges on cell boundaries: every sample is unambiguously in or out.
  const OccupancyRaster r = RasteriseOccupancy({Box({0.25, 0.5}, 0.25, 0.5)}, Options(0.1, 3));
  EXPECT_NEAR(r.OccupiedAreaM2(), 0.5, 1e-12);
  const auto inside = r.CellAt({0.05, 0.05});
  ASSERT_TRUE(inside);
  EXPECT_EQ(r.at(inside->x(), inside->y()), OccupancyRaster::kOccupied);
  const auto outside = r.CellAt({0.55, 0.05});
  ASSERT_TRUE(outside);
  EXPECT_EQ(r.at(outside->x(), outside->y()), OccupancyRaster::kFree);
}

TEST(OccupancyRasterTest, PartialCellsStoreTheirFraction) {
  // The box ends at x = 0.075: 6 of the 8 sample columns of the cell [0, 0.1) x [0, 0.1).
  OccupancyRasterOptions o = Options(0.1, 8);
  const OccupancyRaster r = RasteriseOccupancy({Box({0.025, 0.05}, 0.05, 0.2)}, o);
  const auto cell = r.CellAt({0.05, 0.05});
  ASSERT_TRUE(cell);
  EXPECT_NEAR(r.OccupiedFraction(cell->x(), cell->y()), 6.0 / 8.0, 1.0 / 255.0);
}

TEST(OccupancyRasterTest, InsideRotatedBoxIsOccupiedOutsideIsFree) {
  const MjModelPtr m = Load(R"(
<mujoco>
  <worldbody>
    <geom type="plane" size="5 5 0.1"/>
    <geom name="wall" type="box" pos="0 0 0.5" size="1 0.1 0.5" euler="0 0 45"/>
  </worldbody>
</mujoco>)");
  OccupancyRasterOptions o;
  o.resolution_m = 0.02;
  o.bounds_W = Eigen::AlignedBox2d(Vector2d(-1.5, -1.5), Vector2d(1.5, 1.5));
  const OccupancyRaster r = RasteriseOccupancy(m.get(), o);
  const Vector2d along(std::sqrt(0.5), std::sqrt(0.5));
  const Vector2d across(-std::sqrt(0.5), std::sqrt(0.5));
  EXPECT_TRUE(OccupiedAt(r, 0.9 * along));                    // near the end, on the axis
  EXPECT_TRUE(OccupiedAt(r, -0.5 * along + 0.06 * across));   // inside, near a long face
  EXPECT_FALSE(OccupiedAt(r, -0.5 * along + 0.14 * across));  // outside that face
  EXPECT_FALSE(OccupiedAt(r, 1.1 * along));                   // beyond the end
  // Axis-aligned bounding box corner: inside the AABB, outside the rotated box.
  EXPECT_FALSE(OccupiedAt(r, {0.65, -0.65}));
}

TEST(OccupancyRasterTest, DefaultBoundsAreTheGeometryBoundsAndHeightSelectsTheSlice) {
  const MjModelPtr m = Load(R"(
<mujoco>
  <worldbody>
    <geom type="plane" size="50 50 0.1"/>
    <geom name="leg" type="cylinder" pos="-0.95 -0.45 0.36" size="0.05 0.36"/>
    <geom name="top" type="box" pos="0 0 0.735" size="1.2 0.6 0.015"/>
    <body pos="0 0 0.1">
      <freejoint/>
      <geom type="box" size="3 3 0.1" group="3"/>
    </body>
  </worldbody>
</mujoco>)");
  OccupancyRasterOptions o;
  o.resolution_m = 0.1;
  o.height_m = 0.34;
  const OccupancyRaster low = RasteriseOccupancy(m.get(), o);
  // The table top's footprint, not the 50 m floor nor the robot's 6 m box.
  EXPECT_NEAR(low.origin_xy.x(), -1.2, 1e-12);
  EXPECT_NEAR(low.origin_xy.y(), -0.6, 1e-12);
  EXPECT_EQ(low.width, 24);
  EXPECT_EQ(low.height, 12);
  EXPECT_TRUE(OccupiedAt(low, {-0.95, -0.45}));  // the leg
  EXPECT_FALSE(OccupiedAt(low, {0.0, 0.0}));     // under the table
  o.height_m = 0.74;
  const OccupancyRaster high = RasteriseOccupancy(m.get(), o);
  EXPECT_EQ(high.width, low.width);
  EXPECT_NEAR(high.OccupiedAreaM2(), 2.4 * 1.2, 1e-9);
}

TEST(OccupancyRasterTest, Seed001RoomFreeAreaIsRoomMinusObstacle) {
  const MjModelPtr m =
      LoadModelFromFile((testing::SourceRoot() / "worlds" / "seed001_room_2.xml").string());
  OccupancyRasterOptions o;
  o.resolution_m = 0.01;
  o.height_m = 0.2;
  o.bounds_W = Eigen::AlignedBox2d(Vector2d(-1.75, -1.5), Vector2d(1.75, 1.5));  // inner faces
  const OccupancyRaster r = RasteriseOccupancy(m.get(), o);
  EXPECT_EQ(r.width, 350);
  EXPECT_EQ(r.height, 300);
  const double free_area = 3.5 * 3.0 - r.OccupiedAreaM2();
  EXPECT_NEAR(free_area, 10.5 - 0.57 * 0.57, 4.0 * 0.57 * 0.01);
}

TEST(OccupancyRasterTest, InvalidOptionsNameTheField) {
  const std::vector<UprightGeom> geoms = {Box({0, 0}, 1, 1)};
  const auto expect_field = [&](OccupancyRasterOptions o, const std::string& field) {
    try {
      RasteriseOccupancy(geoms, o);
      ADD_FAILURE() << "expected std::invalid_argument for " << field;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(field + ":", 0), 0u) << e.what();
    }
  };
  OccupancyRasterOptions o;
  o.resolution_m = 0.0;
  expect_field(o, "resolution_m");
  o = {};
  o.supersamples = 9;
  expect_field(o, "supersamples");
  o = {};
  o.bounds_W = Eigen::AlignedBox2d();  // empty
  expect_field(o, "bounds_W");
  EXPECT_THROW(RasteriseOccupancy(std::vector<UprightGeom>{}, OccupancyRasterOptions{}),
               std::invalid_argument);
}

}  // namespace
}  // namespace plywood::sim
