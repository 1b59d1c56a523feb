#include "eval/sonar_map/body_reach.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "eval/sonar_map/squared_distance_transform.h"

namespace plywood::eval {
namespace {

TEST(SquaredDistanceTransformTest, EqualsTheBruteForceMinimumOnARandomGrid) {
  const int width = 37, height = 23;
  std::mt19937 random(7);
  std::vector<char> set(static_cast<std::size_t>(width) * height, 0);
  for (auto& s : set) s = random() % 20 == 0;
  const std::vector<double> d = SquaredDistanceToSet(set, width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double best = kNoSetCell;
      for (int v = 0; v < height; ++v)
        for (int u = 0; u < width; ++u)
          if (set[static_cast<std::size_t>(v) * width + u])
            best = std::min(best, double((x - u) * (x - u) + (y - v) * (y - v)));
      ASSERT_EQ(d[static_cast<std::size_t>(y) * width + x], best) << x << ", " << y;
    }
  const std::vector<double> none = SquaredDistanceToSet(std::vector<char>(12, 0), 4, 3);
  for (double v : none) EXPECT_EQ(v, kNoSetCell);
}

// A 3 x 2 m room at 1 cm, walls one cell thick, cut at x = 2.00-2.10 m by a wall with a gap of
// `gap_m` from y = 0.8 m: a 1.99 x 1.98 m chamber west, a 0.89 x 1.98 m one east.
sim::OccupancyRaster TwoChambers(double gap_m) {
  sim::OccupancyRaster raster;
  raster.resolution_m = 0.01;
  raster.width = 300;
  raster.height = 200;
  raster.cells.assign(300 * 200, sim::OccupancyRaster::kFree);
  const int gap_cells = static_cast<int>(std::lround(gap_m / 0.01));
  for (int iy = 0; iy < raster.height; ++iy)
    for (int ix = 0; ix < raster.width; ++ix) {
      const bool border = ix == 0 || iy == 0 || ix == raster.width - 1 || iy == raster.height - 1;
      const bool cut = ix >= 200 && ix < 210 && !(iy >= 80 && iy < 80 + gap_cells);
      if (border || cut) raster.cells[static_cast<std::size_t>(iy) * 300 + ix] = 255;
    }
  return raster;
}

double FreeArea(const ReachableSpace& space) {
  double cells = 0;
  for (char f : space.free) cells += f != 0;
  return cells * space.raster->resolution_m * space.raster->resolution_m;
}

TEST(BodyReachTest, TheCornersOfTheRobotsOwnRoomCount) {
  // gap 0: the west chamber is closed. A 0.2 m disc leaves its four corners unswept, but it can
  // map them from beside them: every free cell a point reaches counts.
  const sim::OccupancyRaster raster = TwoChambers(0.0);
  const ReachableSpace body = ComputeBodyReachableSpace(raster, {1.0, 1.0}, 0.2);
  EXPECT_EQ(body.free, ComputeReachableSpace(raster, {1.0, 1.0}).free);
  EXPECT_NEAR(FreeArea(body), 1.99 * 1.98, 1e-9);
}

TEST(BodyReachTest, ARoomBehindAGapNarrowerThanTheBodyDoesNotCount) {
  const sim::OccupancyRaster raster = TwoChambers(0.30);
  const Eigen::Vector2d start(1.0, 1.0);
  // A point passes the 0.30 m gap: both chambers and the gap.
  EXPECT_NEAR(FreeArea(ComputeReachableSpace(raster, start)), 1.99 * 1.98 + 0.89 * 1.98 + 0.03,
              1e-9);
  // A 0.2 m disc does not: the west chamber and the gap's west part, which the robot's front pokes
  // into (6.8 cm from a centre 0.132 m short of the wall), not the part that a body in the east
  // chamber would sweep, nor the east chamber.
  const ReachableSpace body = ComputeBodyReachableSpace(raster, start, 0.2);
  EXPECT_GT(FreeArea(body), 1.99 * 1.98 + 0.3 * 0.01);
  EXPECT_LT(FreeArea(body), 1.99 * 1.98 + 0.03);
  EXPECT_TRUE(body.IsFree({2.03, 0.95}));   // the gap's mouth
  EXPECT_FALSE(body.IsFree({2.09, 0.95}));  // the gap's far end
  EXPECT_FALSE(body.IsFree({2.5, 1.0}));    // the east chamber
  EXPECT_FALSE(body.IsFree({2.12, 0.03}));  // a corner of it
}

TEST(BodyReachTest, ABodyNarrowerThanTheGapReachesEverything) {
  const sim::OccupancyRaster raster = TwoChambers(0.45);
  EXPECT_EQ(ComputeBodyReachableSpace(raster, {1.0, 1.0}, 0.2).free,
            ComputeReachableSpace(raster, {1.0, 1.0}).free);
}

TEST(BodyReachTest, AGapPassesFromTwiceTheRadiusLessOneCell) {
  const Eigen::Vector2d start(1.0, 1.0), east(2.5, 1.0);
  EXPECT_TRUE(ComputeBodyReachableSpace(TwoChambers(0.40), start, 0.2).IsFree(east));
  EXPECT_TRUE(ComputeBodyReachableSpace(TwoChambers(0.39), start, 0.2).IsFree(east));
  EXPECT_FALSE(ComputeBodyReachableSpace(TwoChambers(0.38), start, 0.2).IsFree(east));
}

TEST(BodyReachTest, ATruthCutToTheBodyLeavesTheUnreachableChamberUnscored) {
  // The map that calls only the west chamber free: wrong by the whole east chamber and the gap
  // against the point truth, only by the gap's west part against the body truth.
  OccupancyTruth truth;
  truth.raster = TwoChambers(0.30);
  const Eigen::Vector2d start(1.0, 1.0);
  truth.space = ComputeReachableSpace(truth.raster, start);
  truth.FitScoredBox();
  const auto west_only = [](const Eigen::Vector2d& p) { return p.x() < 2.0; };
  const OccupancyError point = ScoreOccupancy(truth, west_only);
  EXPECT_NEAR(point.AreaErrorM2(), 0.89 * 1.98 + 0.03, 1e-9);
  const auto body = MakeBodyReachTruth(truth, start, 0.2);
  const OccupancyError cut = ScoreOccupancy(*body, west_only);
  // Only the gap's west part, free in the truth, is wrong in the map.
  EXPECT_GT(cut.AreaErrorM2(), 0.3 * 0.01);
  EXPECT_LT(cut.AreaErrorM2(), 0.03);
  EXPECT_NEAR(cut.AreaTotalM2(), FreeArea(body->space), 1e-9);
  // The east chamber is unscored: whatever a map says of it, right or wrong, counts for nothing,
  // even inside the scored box (here stretched over it).
  const auto cell = [&](double x, double y) {
    const auto c = truth.raster.CellAt({x, y});
    return static_cast<std::size_t>(c->y()) * truth.raster.width + c->x();
  };
  EXPECT_TRUE(body->unscored[cell(2.5, 1.0)]);
  EXPECT_FALSE(body->unscored[cell(1.0, 1.0)]);
  EXPECT_FALSE(body->unscored[cell(2.5, 1.995)]);  // the outer wall is scored (not free)
  body->x1 = truth.raster.width - 1;
  const auto east_free = [&](const Eigen::Vector2d& p) {  // the east chamber's floor, not its walls
    return west_only(p) || (p.x() > 2.1 && p.x() < 2.99 && p.y() > 0.01 && p.y() < 1.99);
  };
  EXPECT_EQ(ScoreOccupancy(*body, east_free).error_cells,
            ScoreOccupancy(*body, west_only).error_cells);
}

}  // namespace
}  // namespace plywood::eval
