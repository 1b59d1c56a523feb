#include "perception/sonar_map/partition_map.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace plywood::perception {
namespace {

std::vector<Rect> Rects(const PartitionMap& map, Label label) {
  std::vector<Rect> out;
  for (const auto& p : map.partitions())
    if (p.label == label) out.push_back(p.rect);
  std::sort(out.begin(), out.end(), [](const Rect& a, const Rect& b) {
    return std::tie(a.y0, a.x0) < std::tie(b.y0, b.x0);
  });
  return out;
}

// A 10 x 10 room with a 2 x 2 obstacle in the middle.
PartitionMap CentreObstacle() {
  PartitionMap map(Rect{0, 0, 10, 10});
  map.InsertObstacle(Rect{4, 4, 6, 6});
  return map;
}

TEST(PartitionMapTest, InsertObstacleSplitsAlongItsEdgeLines) {
  const PartitionMap map = CentreObstacle();
  EXPECT_EQ(map.partitions().size(), 9u);
  EXPECT_EQ(Rects(map, Label::kObstacle), (std::vector<Rect>{{4, 4, 6, 6}}));
}

TEST(PartitionMapTest, MergeJoinsSameLabelNeighboursWhoseUnionIsARectangle) {
  PartitionMap map = CentreObstacle();
  map.Merge();
  // Along x first: the bottom and top rows become strips; the middle row cannot merge across the
  // obstacle, and [0,4]x[4,6] cannot join the strips (the union is not a rectangle).
  EXPECT_EQ(Rects(map, Label::kFree),
            (std::vector<Rect>{{0, 0, 10, 4}, {0, 4, 4, 6}, {6, 4, 10, 6}, {0, 6, 10, 10}}));
  EXPECT_EQ(Rects(map, Label::kObstacle), (std::vector<Rect>{{4, 4, 6, 6}}));
}

TEST(PartitionMapTest, ObstacleAgainstAWallMergesToThreePartitions) {
  PartitionMap map(Rect{0, 0, 10, 10});
  map.InsertObstacle(Rect{8, 3, 10, 5});  // touches the east wall
  EXPECT_EQ(map.partitions().size(), 6u);
  map.Merge();
  EXPECT_EQ(Rects(map, Label::kFree),
            (std::vector<Rect>{{0, 0, 10, 3}, {0, 3, 8, 5}, {0, 5, 10, 10}}));
}

TEST(PartitionMapTest, SplitAtCornerUsesTheNearestPerpendicularEdge) {
  PartitionMap map(Rect{0, 0, 10, 10});
  // Corner (2, 7): nearest edge is the west one (2 away): a horizontal cut from the corner to it.
  ASSERT_TRUE(map.SplitAtCorner({2, 7}));
  EXPECT_EQ(Rects(map, Label::kFree),
            (std::vector<Rect>{{0, 0, 2, 7}, {2, 0, 10, 10}, {0, 7, 2, 10}}));
  // A corner on an edge is not strictly inside anything new... (2, 7) lies on edges now.
  EXPECT_FALSE(map.SplitAtCorner({2, 7}));
  // Corner (6, 9.5): nearest is the north edge: a vertical cut up to it.
  ASSERT_TRUE(map.SplitAtCorner({6, 9.5}));
  EXPECT_EQ(map.partitions().size(), 5u);
  map.Merge();
  EXPECT_EQ(map.partitions().size(), 1u);  // everything free again: one rectangle
  EXPECT_EQ(map.partitions()[0].rect, (Rect{0, 0, 10, 10}));
}

TEST(PartitionGraphTest, AdjacencyNegativeExperienceAndGraphOnAHandMadeMap) {
  PartitionMap map = CentreObstacle();
  map.Merge();
  const auto adjacency = map.Adjacencies();
  // bottom, top each touch left, right and obstacle; left and right touch the obstacle.
  EXPECT_EQ(adjacency.size(), 8u);
  const NegativeExperience d = InitialNegativeExperience(map, adjacency, 0.45);
  EXPECT_EQ(d.size(), 4u);  // the four transitions into the obstacle
  const int obstacle = map.Find({5, 5});
  const int left = map.Find({1, 5});
  EXPECT_TRUE(d.Forbidden(obstacle, left));
  EXPECT_TRUE(d.Forbidden(left, obstacle));
  const TopologicalGraph g = BuildGraph(map, adjacency, d);
  EXPECT_EQ(g.nodes.size(), 4u);
  EXPECT_EQ(g.arcs.size(), 4u);  // a ring around the obstacle

  // A narrow stretch goes into D too: make the left passage 0.3 wide.
  PartitionMap narrow(Rect{0, 0, 10, 10});
  narrow.InsertObstacle(Rect{0.3, 4, 6, 6});
  narrow.Merge();
  const auto adj2 = narrow.Adjacencies();
  const NegativeExperience d2 = InitialNegativeExperience(narrow, adj2, 0.45);
  const TopologicalGraph g2 = BuildGraph(narrow, adj2, d2);
  EXPECT_EQ(g2.nodes.size(), 4u);
  EXPECT_EQ(g2.arcs.size(), 2u);  // only through the right-hand side
}

TEST(PartitionGraphTest, ShortestPathMovesParallelToTheAxes) {
  PartitionMap map = CentreObstacle();
  map.Merge();
  const auto adjacency = map.Adjacencies();
  const TopologicalGraph g =
      BuildGraph(map, adjacency, InitialNegativeExperience(map, adjacency, 0.45));
  const Eigen::Vector2d from(1, 5), to(9, 5);  // left of the obstacle to right of it
  const auto path = PlanPath(map, g, from, to);
  ASSERT_FALSE(path.empty());
  EXPECT_EQ(path.back(), to);
  Eigen::Vector2d at = from;
  double length = 0.0;
  for (const auto& p : path) {
    EXPECT_TRUE(p.x() == at.x() || p.y() == at.y());  // x or y moves only
    const int i = map.Find(0.5 * (p + at));
    ASSERT_GE(i, 0);
    EXPECT_EQ(map.partitions()[i].label, Label::kFree);
    length += (p - at).norm();
    at = p;
  }
  // Via the bottom strip's door midpoints (2, 4) and (8, 4): 1+1 + 6 + 1+1 = 10.
  EXPECT_NEAR(length, 10.0, 1e-12);
  // Unreachable: nothing connects to a point outside.
  EXPECT_TRUE(PlanPath(map, g, from, {11, 5}).empty());
}

}  // namespace
}  // namespace plywood::perception
