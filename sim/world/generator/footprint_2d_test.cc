#include "sim/world/generator/footprint_2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace plywood::sim::worldgen {
namespace {

using Eigen::Vector2d;

TEST(Footprint2dTest, BoxCornersRunCounterClockwiseFromThePlusXFace) {
  const Footprint f = Footprint::Box({1, 2}, {0.5, 0.25}, std::numbers::pi / 2);
  ASSERT_EQ(f.corners.size(), 4u);
  EXPECT_NEAR((f.corners[0] - Vector2d(1.25, 2.5)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((f.corners[1] - Vector2d(0.75, 2.5)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((f.corners[2] - Vector2d(0.75, 1.5)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((f.corners[3] - Vector2d(1.25, 1.5)).norm(), 0.0, 1e-12);
}

TEST(Footprint2dTest, DistancesMatchClosedForm) {
  const Footprint box = Footprint::Box({0, 0}, {1, 0.5}, 0.0);
  EXPECT_DOUBLE_EQ(DistanceToPoint(box, {0.3, 0.2}), 0.0);
  EXPECT_NEAR(DistanceToPoint(box, {3, 0}), 2.0, 1e-12);
  EXPECT_NEAR(DistanceToPoint(box, {4, 4.5}), 5.0, 1e-12);  // to the corner (1, 0.5)
  const Footprint disc = Footprint::Disc({5, 0}, 1.0);
  EXPECT_NEAR(Distance(box, disc), 3.0, 1e-12);
  EXPECT_NEAR(Distance(disc, Footprint::Disc({5, 4}, 0.5)), 2.5, 1e-12);
  // A box turned 45 deg: its corner points at the other box.
  const double s = std::sqrt(0.5);
  const Footprint diamond = Footprint::Box({3, 0}, {s, s}, std::numbers::pi / 4);
  EXPECT_NEAR(Distance(box, diamond), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(Distance(box, Footprint::Box({0.5, 0}, {0.1, 0.1}, 0.3)), 0.0);  // inside
}

TEST(Footprint2dTest, TouchingIsNotOverlapping) {
  const Footprint a = Footprint::Box({0, 0}, {1, 1}, 0.0);
  const Footprint touching = Footprint::Box({2, 0.5}, {1, 1}, 0.0);
  const Footprint overlapping = Footprint::Box({1.99, 0.5}, {1, 1}, 0.0);
  EXPECT_DOUBLE_EQ(Distance(a, touching), 0.0);
  EXPECT_FALSE(Overlap(a, touching, 1e-9));
  EXPECT_TRUE(Overlap(a, overlapping, 1e-9));
  EXPECT_FALSE(Overlap(a, Footprint::Disc({2, 0}, 1.0), 1e-9));
  EXPECT_TRUE(Overlap(a, Footprint::Disc({2, 0}, 1.01), 1e-9));
}

TEST(Footprint2dTest, RaysHitTheNearestBoundary) {
  const Footprint box = Footprint::Box({3, 0}, {1, 1}, 0.0);
  EXPECT_NEAR(*RayHit(box, {0, 0}, {1, 0}), 2.0, 1e-12);
  EXPECT_FALSE(RayHit(box, {0, 0}, {-1, 0}).has_value());
  EXPECT_FALSE(RayHit(box, {0, 0}, {0, 1}).has_value());
  EXPECT_DOUBLE_EQ(*RayHit(box, {3, 0}, {1, 0}), 0.0);
  const Footprint disc = Footprint::Disc({0, 5}, 1.0);
  EXPECT_NEAR(*RayHit(disc, {0, 0}, {0, 1}), 4.0, 1e-12);
  EXPECT_FALSE(RayHit(disc, {0, 0}, {1, 0}).has_value());
}

TEST(Footprint2dTest, PointInPolygonHandlesAnLShape) {
  const std::vector<Vector2d> l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_TRUE(InsidePolygon(l, {0.5, 0.5}));
  EXPECT_TRUE(InsidePolygon(l, {0.5, 1.5}));
  EXPECT_FALSE(InsidePolygon(l, {1.5, 1.5}));
  EXPECT_FALSE(InsidePolygon(l, {3, 0.5}));
}

}  // namespace
}  // namespace plywood::sim::worldgen
