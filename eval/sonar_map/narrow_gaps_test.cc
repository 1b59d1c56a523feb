#include "eval/sonar_map/narrow_gaps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace plywood::eval {
namespace {

// Brute force: a cell is covered when some k x k square of set cells, wholly inside the grid,
// contains it.
std::vector<char> CoveredByBruteForce(const std::vector<char>& set, int width, int height, int k) {
  std::vector<char> covered(set.size(), 0);
  for (int y0 = 0; y0 + k <= height; ++y0)
    for (int x0 = 0; x0 + k <= width; ++x0) {
      bool fits = true;
      for (int y = y0; y < y0 + k && fits; ++y)
        for (int x = x0; x < x0 + k && fits; ++x) fits = set[y * width + x] != 0;
      if (!fits) continue;
      for (int y = y0; y < y0 + k; ++y)
        for (int x = x0; x < x0 + k; ++x) covered[y * width + x] = 1;
    }
  return covered;
}

TEST(CellsASquareCoversTest, EqualsTheBruteForceOpeningOnRandomGrids) {
  std::mt19937 random(11);
  for (int trial = 0; trial < 40; ++trial) {
    const int width = 5 + static_cast<int>(random() % 30),
              height = 5 + static_cast<int>(random() % 20);
    const int k = 1 + static_cast<int>(random() % 6);
    std::vector<char> set(static_cast<std::size_t>(width) * height, 0);
    for (auto& s : set) s = random() % 5 != 0;
    ASSERT_EQ(CellsASquareCovers(set, width, height, k), CoveredByBruteForce(set, width, height, k))
        << "trial " << trial << ", " << width << " x " << height << ", k " << k;
  }
}

TEST(CellsASquareCoversTest, DropsACorridorNarrowerThanTheSquareAndKeepsARoomsCorners) {
  // A 6 x 6 room (x 0-5) joined to a 4 x 6 one (x 9-12) by a corridor 2 cells wide (x 6-8, y 2-3).
  const int width = 13, height = 6;
  std::vector<char> set(width * height, 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) set[y * width + x] = x <= 5 || x >= 9 || (y >= 2 && y <= 3);
  const std::vector<char> covered = CellsASquareCovers(set, width, height, 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      EXPECT_EQ(covered[y * width + x] != 0, x <= 5 || x >= 9) << x << ", " << y;
  // A square of the corridor's width passes it.
  EXPECT_EQ(CellsASquareCovers(set, width, height, 2), set);
}

// A 3 x 2 m room at 1 cm (walls one cell thick) holding a 1.0 x 0.5 m box whose south face is
// `gap_m` from the south wall's face, x 1.0-2.0 m.
OccupancyTruth RoomWithABox(double gap_m) {
  OccupancyTruth truth;
  sim::OccupancyRaster& raster = truth.raster;
  raster.resolution_m = 0.01;
  raster.width = 300;
  raster.height = 200;
  raster.cells.assign(300 * 200, sim::OccupancyRaster::kFree);
  const int gap = static_cast<int>(std::lround(gap_m / 0.01));
  for (int iy = 0; iy < raster.height; ++iy)
    for (int ix = 0; ix < raster.width; ++ix) {
      const bool border = ix == 0 || iy == 0 || ix == raster.width - 1 || iy == raster.height - 1;
      const bool box = ix >= 100 && ix < 200 && iy >= 1 + gap && iy < 1 + gap + 50;
      if (border || box) raster.cells[static_cast<std::size_t>(iy) * 300 + ix] = 255;
    }
  truth.space = ComputeReachableSpace(raster, {0.5, 1.5});
  truth.FitScoredBox();
  return truth;
}

int Unscored(const OccupancyTruth& truth) {
  int n = 0;
  for (char u : truth.unscored) n += u != 0;
  return n;
}

TEST(TruthWithoutNarrowGapsTest, LeavesAGapNarrowerThanTheBodyUnscoredAndScoresTheRest) {
  const OccupancyTruth truth = RoomWithABox(0.30);
  const auto wide = MakeTruthWithoutNarrowGaps(truth, 0.43);
  // The 0.30 m x 1.0 m strip between the box and the south wall, and nothing else: the room's
  // corners and the box's outer corners take a square of the body's width.
  EXPECT_EQ(Unscored(*wide), 30 * 100);
  EXPECT_EQ(wide->x0, truth.x0);
  EXPECT_EQ(wide->y1, truth.y1);
  // A map that keeps the gap obstacle (as the seed's rule does) is wrong by the gap under e and
  // right under the new truth; one that calls it free is right under e and not blamed here either.
  const auto gap_is_obstacle = [](const Eigen::Vector2d& p) {
    return !(p.x() > 1.0 && p.x() < 2.0 && p.y() < 0.81);
  };
  const OccupancyError e = ScoreOccupancy(truth, gap_is_obstacle);
  EXPECT_EQ(e.error_cells, 30 * 100);
  EXPECT_EQ(ScoreOccupancy(*wide, gap_is_obstacle).error_cells, 0);
  const auto true_map = [&](const Eigen::Vector2d& p) { return truth.space.IsFree(p); };
  EXPECT_EQ(ScoreOccupancy(*wide, true_map).error_cells, 0);
  EXPECT_EQ(ScoreOccupancy(*wide, true_map).total_cells, e.total_cells - 30 * 100);
}

TEST(TruthWithoutNarrowGapsTest, AGapTheBodyFitsStaysScored) {
  // 0.43 m: exactly the body's width (43 cells), so a square fits it; 0.42 m does not.
  EXPECT_EQ(Unscored(*MakeTruthWithoutNarrowGaps(RoomWithABox(0.43), 0.43)), 0);
  EXPECT_EQ(Unscored(*MakeTruthWithoutNarrowGaps(RoomWithABox(0.42), 0.43)), 42 * 100);
  EXPECT_EQ(Unscored(*MakeTruthWithoutNarrowGaps(RoomWithABox(0.60), 0.43)), 0);
}

TEST(TruthWithoutNarrowGapsTest, RefusesABodyWithoutWidth) {
  const OccupancyTruth truth = RoomWithABox(0.30);
  EXPECT_THROW(MakeTruthWithoutNarrowGaps(truth, 0.0), std::invalid_argument);
  EXPECT_THROW(MakeTruthWithoutNarrowGaps(truth, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace plywood::eval
