#include "sim/world/generator/wall_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/world/generator/footprint_2d.h"

namespace plywood::sim::worldgen {
namespace {

using Eigen::Vector2d;
constexpr double kPi = std::numbers::pi;

TEST(WallBuilderTest, MitreReachesWhereTheOuterFacesMeet) {
  const double t = kWallThicknessM;
  EXPECT_NEAR(MitreExtensionM(kPi / 2), t, 1e-15);                       // 90 deg corner
  EXPECT_NEAR(MitreExtensionM(2 * kPi / 3), t * std::sqrt(3.0), 1e-15);  // 60 deg corner
  EXPECT_NEAR(MitreExtensionM(kPi / 3), t / std::sqrt(3.0), 1e-15);      // 120 deg corner
  EXPECT_EQ(MitreExtensionM(-kPi / 2), 0.0);                             // reflex corner
}

// Every point of the band 18 mm outside the outline is covered by some wall, and no wall reaches
// into the room: the walls close the room and leave its floor free.
void ExpectClosedAndClear(const std::vector<Vector2d>& outline, const GeneratedWorld& world) {
  const std::vector<Footprint> walls = world.Footprints();
  const size_t n = outline.size();
  for (size_t i = 0; i < n; ++i) {
    const Vector2d a = outline[i], b = outline[(i + 1) % n];
    const Vector2d along = (b - a).normalized(), outward(along.y(), -along.x());
    for (double u = 0.0; u <= 1.0; u += 0.01) {
      for (const double v : {0.0005, 0.009, 0.0175}) {
        const Vector2d p = a + u * (b - a) + v * outward;
        double d = 1.0;
        for (const Footprint& f : walls) d = std::min(d, DistanceToPoint(f, p));
        EXPECT_EQ(d, 0.0) << "edge " << i << " u " << u << " v " << v;
      }
      const Vector2d inside = a + u * (b - a) - 0.0005 * outward;
      if (u > 0.01 && u < 0.99 && InsidePolygon(outline, inside)) {
        for (const Footprint& f : walls) EXPECT_GT(DistanceToPoint(f, inside), 0.0);
      }
    }
  }
}

TEST(WallBuilderTest, RectangleInnerFacesLieOnTheOutline) {
  const std::vector<Vector2d> outline = {{0, 0}, {4, 0}, {4, 3}, {0, 3}};
  GeneratedWorld world;
  const auto built = AddOutlineWalls(world, outline, std::vector<OutlineEdge>(4));
  ASSERT_EQ(world.geoms.size(), 4u);
  EXPECT_EQ(world.geoms[0].name, "wall_0");
  EXPECT_EQ(built[2], std::vector<int>{2});
  // The south wall: inner face y = 0, 18 mm thick outward, reaching 18 mm past both corners.
  const WorldGeom& south = world.geoms[0];
  EXPECT_NEAR(south.centre.x(), 2.0, 1e-12);
  EXPECT_NEAR(south.centre.y(), -0.009, 1e-12);
  EXPECT_NEAR(south.half_size.x(), 2.018, 1e-12);
  EXPECT_NEAR(south.half_size.y(), 0.009, 1e-12);
  EXPECT_NEAR(south.yaw_deg, 0.0, 1e-12);
  ExpectClosedAndClear(outline, world);
}

TEST(WallBuilderTest, SkewedAndReflexCornersClose) {
  // 60, 120, 120 and 60 deg corners, then an L with a reflex corner.
  const double h = std::sqrt(3.0);
  const std::vector<Vector2d> trapezoid = {{0, 0}, {4, 0}, {3, h}, {1, h}};
  GeneratedWorld world;
  AddOutlineWalls(world, trapezoid, std::vector<OutlineEdge>(4));
  ExpectClosedAndClear(trapezoid, world);
  const std::vector<Vector2d> l = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
  GeneratedWorld l_world;
  AddOutlineWalls(l_world, l, std::vector<OutlineEdge>(6));
  ExpectClosedAndClear(l, l_world);
}

TEST(WallBuilderTest, OpeningsLeaveAGapWithSquareJambs) {
  const std::vector<Vector2d> outline = {{0, 0}, {4, 0}, {4, 3}, {0, 3}};
  std::vector<OutlineEdge> edges(4);
  edges[0].openings = {{1.0, 1.8}};
  edges[2].built = false;
  GeneratedWorld world;
  const auto built = AddOutlineWalls(world, outline, edges);
  EXPECT_EQ(built[0].size(), 2u);
  EXPECT_TRUE(built[2].empty());
  ASSERT_EQ(world.geoms.size(), 4u);  // two south pieces, east, west
  // West piece of the south wall: from x = -0.018 (mitre) to the jamb at x = 1.
  const WorldGeom& west_piece = world.geoms[0];
  EXPECT_NEAR(west_piece.centre.x() - west_piece.half_size.x(), -0.018, 1e-12);
  EXPECT_NEAR(west_piece.centre.x() + west_piece.half_size.x(), 1.0, 1e-12);
  // The east wall stops square at the missing north wall: y = 3, no mitre.
  const WorldGeom& east = world.geoms[2];
  EXPECT_NEAR(east.centre.y() + east.half_size.x(), 3.0, 1e-12);
  for (const Footprint& f : world.Footprints()) {
    EXPECT_GT(DistanceToPoint(f, {1.4, -0.009}), 0.39);  // the doorway is open
  }
}

TEST(WallBuilderTest, SimplifyDropsCollinearAndRepeatedCorners) {
  const std::vector<Vector2d> raw = {{0, 0}, {1, 0}, {2, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 1}};
  const auto simple = SimplifyOutline(raw);
  ASSERT_EQ(simple.size(), 4u);
  EXPECT_NEAR(SignedArea(simple), 4.0, 1e-12);
}

}  // namespace
}  // namespace plywood::sim::worldgen
