#include "perception/geometric_map/map_aggregation.h"

#include <gtest/gtest.h>

namespace plywood::perception {
namespace {

MapSegment Segment(Eigen::Vector2d a, Eigen::Vector2d b, int points = 20, bool pseudo = false) {
  MapSegment s;
  s.line.start = a;
  s.line.end = b;
  s.line.num_points = points;
  s.inliers = points;
  s.pseudo = pseudo;
  return s;
}

TEST(MapAggregationTest, OverlappingCollinearSegmentsMergeToTheOutermostEndpoints) {
  GeometricMap map;
  map.AddSegment(Segment({0.0, 1.0}, {2.0, 1.0}));
  map.AddSegment(Segment({1.5, 1.0}, {3.0, 1.0}));
  ASSERT_EQ(map.segments().size(), 1u);
  const LineSegment& l = map.segments()[0].line;
  EXPECT_NEAR((l.start - Eigen::Vector2d(0.0, 1.0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((l.end - Eigen::Vector2d(3.0, 1.0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(l.r_m, 1.0, 1e-12);
  EXPECT_NEAR(l.alpha_rad, std::numbers::pi / 2.0, 1e-12);
  EXPECT_EQ(l.num_points, 40);
}

TEST(MapAggregationTest, WeightedMeanOrientation) {
  GeometricMap map;
  // 3 parts at 0 deg and 1 part at 2 deg (both through (1, 0)): the merged line is at 0.5 deg.
  const double t = 2.0 * std::numbers::pi / 180.0;
  map.AddSegment(Segment({0.0, 0.0}, {2.0, 0.0}, 30));
  map.AddSegment(Segment({1.0 - std::cos(t), -std::sin(t)}, {1.0 + std::cos(t), std::sin(t)}, 10));
  ASSERT_EQ(map.segments().size(), 1u);
  const Eigen::Vector2d d = map.segments()[0].line.end - map.segments()[0].line.start;
  EXPECT_NEAR(std::atan2(d.y(), d.x()), t / 4.0, 1e-12);
}

TEST(MapAggregationTest, ParallelSegmentsThirtyCentimetresApartStaySeparate) {
  GeometricMap map;
  map.AddSegment(Segment({0.0, 1.0}, {2.0, 1.0}));
  map.AddSegment(Segment({0.5, 1.3}, {2.5, 1.3}));
  EXPECT_EQ(map.segments().size(), 2u);
}

TEST(MapAggregationTest, OppositeFacesAndDoorwaysStaySeparate) {
  GeometricMap map;
  map.AddSegment(Segment({0.0, 1.0}, {2.0, 1.0}));
  // The other face of an 18 mm partition, seen from its other side (so directed the other way).
  map.AddSegment(Segment({2.0, 1.018}, {0.0, 1.018}));
  // The same wall beyond a 0.9 m doorway.
  map.AddSegment(Segment({2.9, 1.0}, {4.0, 1.0}));
  EXPECT_EQ(map.segments().size(), 3u);
}

TEST(MapAggregationTest, PseudoSideSeenForRealBecomesReal) {
  GeometricMap map;
  map.AddSegment(Segment({0.0, 3.0}, {2.0, 3.0}, 1, true));
  ASSERT_TRUE(map.segments()[0].pseudo);
  map.AddSegment(Segment({0.5, 3.02}, {1.5, 3.02}, 20));
  ASSERT_EQ(map.segments().size(), 1u);
  EXPECT_FALSE(map.segments()[0].pseudo);
  EXPECT_NEAR(map.segments()[0].line.start.x(), 0.5, 1e-12);
}

TEST(MapAggregationTest, TouchingClustersMerge) {
  GeometricMap map;
  map.AddCluster({Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(0.1, 0.1)), 4});
  map.AddCluster({Eigen::AlignedBox2d(Eigen::Vector2d(0.12, 0), Eigen::Vector2d(0.2, 0.1)), 3});
  map.AddCluster({Eigen::AlignedBox2d(Eigen::Vector2d(1, 1), Eigen::Vector2d(1.1, 1.1)), 5});
  ASSERT_EQ(map.clusters().size(), 2u);
  EXPECT_EQ(map.clusters()[0].points + map.clusters()[1].points, 12);
}

}  // namespace
}  // namespace plywood::perception
