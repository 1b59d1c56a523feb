#include "perception/sonar_map/escape_cells.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "perception/sonar_map/cell_dilation.h"
#include "perception/sonar_map/frontier_planner.h"

namespace plywood::perception {
namespace {

// A 40 x 40 raster of 5 cm cells with a box in its south-east: cells x 24-39, y 0-19 (the
// box's north-west corner cell is (24, 19)). Everything else is free.
constexpr int kW = 40, kH = 40;
constexpr int kBoxX0 = 24, kBoxY1 = 19;

std::size_t Index(int ix, int iy) { return static_cast<std::size_t>(iy) * kW + ix; }

std::vector<char> Box() {
  std::vector<char> box(static_cast<std::size_t>(kW) * kH, 0);
  for (int iy = 0; iy <= kBoxY1; ++iy)
    for (int ix = kBoxX0; ix < kW; ++ix) box[Index(ix, iy)] = 1;
  return box;
}

// The free cells within `radius` cells of `start` (what the planner lets a robot standing too
// close to something use).
std::vector<char> Around(const std::vector<char>& box, const Eigen::Vector2i& start,
                         double radius) {
  std::vector<char> around(box.size(), 0);
  for (int iy = 0; iy < kH; ++iy)
    for (int ix = 0; ix < kW; ++ix)
      around[Index(ix, iy)] =
          !box[Index(ix, iy)] && std::hypot(ix - start.x(), iy - start.y()) < radius;
  return around;
}

// Distance (cells) from a point to the nearest box cell centre.
double Clearance(const std::vector<char>& box, const Eigen::Vector2d& p) {
  double best = std::numeric_limits<double>::infinity();
  for (int iy = 0; iy < kH; ++iy)
    for (int ix = 0; ix < kW; ++ix)
      if (box[Index(ix, iy)]) best = std::min(best, std::hypot(p.x() - ix, p.y() - iy));
  return best;
}

// The planner's way from `start` to `goal` over the cells that keep `radius` from the box or
// are `escape` cells, string-pulled; returns the least clearance along its legs (sampled every
// tenth of a cell).
double LeastClearanceOnPath(const std::vector<char>& box, const std::vector<char>& escape,
                            const Eigen::Vector2i& start, const Eigen::Vector2i& goal,
                            double radius) {
  const std::vector<char> near = Dilate(box, kW, kH, radius);
  std::vector<char> traversable(box.size(), 0), goals(box.size(), 0);
  for (std::size_t i = 0; i < box.size(); ++i) traversable[i] = !near[i] || escape[i];
  goals[Index(goal.x(), goal.y())] = 1;
  const std::vector<Eigen::Vector2i> cells = ShortestCellPath(traversable, goals, kW, kH, start);
  EXPECT_FALSE(cells.empty());
  const std::vector<Eigen::Vector2i> path = SimplifyPath(cells, traversable, kW, kH);
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < path.size(); ++k) {
    const Eigen::Vector2d a = path[k - 1].cast<double>(), b = path[k].cast<double>();
    const int n = static_cast<int>(std::ceil((b - a).norm() * 10.0));
    for (int j = 0; j <= n; ++j) least = std::min(least, Clearance(box, a + (b - a) * j / n));
  }
  return least;
}

TEST(EscapeCellsTest, NearestBlockedDistanceIsTheSquaredCellDistanceWithinTheRadius) {
  const std::vector<char> box = Box();
  // (17, 14) is 7 cells west of the box's west face.
  EXPECT_EQ(NearestBlockedDistance2(box, kW, kH, 17, 14, 9.0), 49);
  // (20, 23): 4 cells west and 4 north of the corner cell.
  EXPECT_EQ(NearestBlockedDistance2(box, kW, kH, 20, 23, 9.0), 32);
  // Nothing within the radius.
  EXPECT_EQ(NearestBlockedDistance2(box, kW, kH, 5, 35, 9.0), -1);
  EXPECT_EQ(NearestBlockedDistance2(box, kW, kH, 17, 14, 6.9), -1);
}

TEST(EscapeCellsTest, ARobotTooCloseToABoxMayLeaveButGetsNoNearer) {
  const std::vector<char> box = Box();
  // As in layout 3 at seed 18: the robot stands 6 cells (0.30 m) west of the box's face, below
  // its corner, on a narrow path (clearance 7 cells, 0.35 m); the free cells within 9 cells
  // (0.45 m, the path clearance) of it are what it may use to leave.
  const Eigen::Vector2i start(18, 17);
  constexpr double kClearance = 7.0, kAround = 9.0;
  const std::vector<char> around = Around(box, start, kAround);
  const std::vector<char> escape = EscapeCells(around, box, kW, kH, start, kClearance);
  // The robot's own cell, and the cells along the face at its distance, stay usable; moving
  // away from the face too.
  EXPECT_TRUE(escape[Index(18, 17)]);
  EXPECT_TRUE(escape[Index(18, 10)]);
  EXPECT_TRUE(escape[Index(12, 17)]);
  // Nearer to the face or to the corner is not.
  EXPECT_FALSE(escape[Index(19, 17)]);
  EXPECT_FALSE(escape[Index(21, 22)]);  // 4.2 cells from the corner cell
  for (std::size_t i = 0; i < escape.size(); ++i) {
    if (escape[i]) {
      EXPECT_TRUE(around[i]);
    }
  }

  // A goal north-east past the corner: the way there keeps the robot's own clearance (less the
  // half cell a leg between two cell centres can come nearer), where the rule before (every free
  // cell near the robot usable) cut the corner more than a cell nearer than the robot stood.
  const Eigen::Vector2i goal(30, 32);
  EXPECT_GE(LeastClearanceOnPath(box, escape, start, goal, kClearance), 6.0 - 0.5);
  EXPECT_LT(LeastClearanceOnPath(box, around, start, goal, kClearance), 6.0 - 1.0);
}

TEST(EscapeCellsTest, ARobotKeepingTheClearanceGetsNoCellThatDoesNot) {
  const std::vector<char> box = Box();
  const Eigen::Vector2i start(10, 14);  // 14 cells from the face
  const std::vector<char> around = Around(box, start, 9.0);
  const std::vector<char> escape = EscapeCells(around, box, kW, kH, start, 9.0);
  const std::vector<char> near = Dilate(box, kW, kH, 9.0);
  for (int iy = 0; iy < kH; ++iy)
    for (int ix = 0; ix < kW; ++ix)
      EXPECT_EQ(escape[Index(ix, iy)], around[Index(ix, iy)] && !near[Index(ix, iy)])
          << ix << "," << iy;
}

// EscapeCells takes every cell's nearest blocking cell from per-row distances: the same answer as
// asking NearestBlockedDistance2 cell by cell (the definition), on random rasters, robots and
// radii.
TEST(EscapeCellsTest, EveryCellIsJudgedByItsNearestBlockingCellAsOneByOne) {
  std::mt19937 rng(11);
  int cases = 0;
  for (const int width : {1, 5, 31, 60})
    for (const int height : {1, 4, 45})
      for (const double fill : {0.0, 0.01, 0.1, 0.5})
        for (const double radius : {0.0, 1.0, 2.5, 6.0, 9.0, 9.0 - 1e-9, 30.0}) {
          std::bernoulli_distribution blocked_draw(fill), around_draw(0.4);
          std::vector<char> blocked(static_cast<std::size_t>(width) * height),
              around(blocked.size());
          for (char& c : blocked) c = blocked_draw(rng) ? 1 : 0;
          for (char& c : around) c = around_draw(rng) ? 1 : 0;
          const Eigen::Vector2i start(static_cast<int>(rng() % width),
                                      static_cast<int>(rng() % height));
          std::vector<char> expected(blocked.size(), 0);
          const int own =
              NearestBlockedDistance2(blocked, width, height, start.x(), start.y(), radius);
          for (int iy = 0; iy < height; ++iy)
            for (int ix = 0; ix < width; ++ix) {
              const std::size_t i = static_cast<std::size_t>(iy) * width + ix;
              if (!around[i]) continue;
              const int d2 = NearestBlockedDistance2(blocked, width, height, ix, iy, radius);
              expected[i] = d2 < 0 || (own >= 0 && d2 >= own);
            }
          ASSERT_EQ(EscapeCells(around, blocked, width, height, start, radius), expected)
              << width << " x " << height << ", fill " << fill << ", radius " << radius;
          ++cases;
        }
  EXPECT_EQ(cases, 4 * 3 * 4 * 7);
}

}  // namespace
}  // namespace plywood::perception
