#include "perception/sonar_map/echo_passage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "perception/sonar_map/frontier_planner.h"

namespace plywood::perception {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSide = 80;  // 5 cm cells from (0, 0), 4 x 4 m

LogOddsGridOptions Geometry() {
  LogOddsGridOptions g;
  g.resolution_m = 0.05;
  g.origin_xy = {0.0, 0.0};
  g.width = g.height = kSide;
  return g;
}

std::size_t Index(int ix, int iy) { return static_cast<std::size_t>(iy) * kSide + ix; }

// One transducer at the robot's centre looking `bearing` off its heading.
msgs::RangeRing Ring(double bearing_rad, double range_m) {
  msgs::RangeRing ring;
  msgs::RangeReading r;
  r.X_RS = {0.0, 0.0, bearing_rad};
  r.range_m = range_m;
  r.echo = true;
  ring.readings.push_back(r);
  return ring;
}

// Distance from a point to an axis-parallel box [x0, x1] x [y0, y1].
double DistanceToBox(double x, double y, double x0, double y0, double x1, double y1) {
  const double dx = std::max({x0 - x, 0.0, x - x1}), dy = std::max({y0 - y, 0.0, y - y1});
  return std::hypot(dx, dy);
}

// Two boxes x in [1.5, 2.5], one up to y = 1.69, one from y = 2.31: a passage 0.62 m wide, wider
// than the robot (0.406 m) with 0.10 m a side. Heard: every cell holding box; plus the network's
// blur, which paints each of the four corners out by a cell along the passage's mouth (x 1.40-1.50
// and 2.50-2.60, in the rows next to the faces). Grid-aligned axes pass those painted cells twice
// (looking north across the mouth, echo off a wall at y 3.9) and hear the boxes' west and east
// faces head-on. As heard, no cell of the passage keeps the squeeze clearance (0.30 m) from the
// heard cells; without the paint the axes saw through, the passage's centre line does, and it keeps
// the robot and the front check's margin (0.25 m) from the true boxes.
TEST(EchoPassageTest, PaintTheAxesSawThroughIsDroppedAndAPaintedPassageOpensOnItsCentreLine) {
  constexpr double kSouthTop = 1.69, kNorthBottom = 2.31, kX0 = 1.5, kX1 = 2.5;
  std::vector<char> heard(static_cast<std::size_t>(kSide) * kSide, 0), box(heard.size(), 0);
  // The cells holding box: columns 30-49 (x 1.50-2.50), rows 24-33 (y 1.20-1.70, the face at 1.69
  // in row 33) and 46-55 (y 2.30-2.80, the face at 2.31 in row 46).
  for (int iy = 0; iy < kSide; ++iy)
    for (int ix = 30; ix <= 49; ++ix)
      if ((iy >= 24 && iy <= 33) || (iy >= 46 && iy <= 55)) box[Index(ix, iy)] = 1;
  heard = box;
  // Faces in rows 33 (y 1.65-1.70) and 46 (y 2.30-2.35); the corners painted one cell out in x.
  for (const int ix : {29, 50})
    for (const int iy : {33, 34, 45, 46}) heard[Index(ix, iy)] = 1;

  BeamFreeGrid beam_free(Geometry(), {});
  for (int pass = 0; pass < 2; ++pass)
    for (const double x : {1.47, 2.52}) {
      // North across the mouth from y 0.2, echo off a wall at y 3.9.
      beam_free.Integrate(Ring(0.5 * kPi, 3.7), {x, 0.2, 0.0});
      // The boxes' west and east faces heard head-on from 0.3 m off them (echo 1 cm inside).
      for (const double y : {1.42, 1.57, 2.42, 2.57}) {
        const bool west = x < 2.0;
        beam_free.Integrate(Ring(0.0, 0.31), {west ? kX0 - 0.3 : kX1 + 0.3, y, west ? 0.0 : kPi});
      }
    }

  const std::vector<char> kept = HeardWithoutAxisFreePaint(heard, beam_free, 2, 1);
  for (int iy = 0; iy < kSide; ++iy)
    for (int ix = 0; ix < kSide; ++ix) {
      SCOPED_TRACE(::testing::Message() << ix << ", " << iy);
      // Every cell of a box stays; of the paint, what the axes passed twice goes.
      if (box[Index(ix, iy)]) {
        EXPECT_TRUE(kept[Index(ix, iy)]);
      } else if (heard[Index(ix, iy)]) {
        EXPECT_FALSE(kept[Index(ix, iy)]);
      }
    }

  // Planning at the squeeze clearance over the free cells: west of the boxes to east of them.
  const double clearance_cells = 0.30 / 0.05;
  std::vector<char> goal(heard.size(), 0);
  for (int iy = 0; iy < kSide; ++iy) goal[Index(60, iy)] = 1;
  const Eigen::Vector2i start(20, 40);
  auto plan = [&](const std::vector<char>& blocking) {
    const std::vector<char> near = Dilate(blocking, kSide, kSide, clearance_cells);
    std::vector<char> traversable(heard.size(), 0);
    for (std::size_t i = 0; i < heard.size(); ++i) traversable[i] = !near[i] && !heard[i];
    // Round the boxes is no way: the room is y 1.2-2.8 here.
    for (int ix = 0; ix < kSide; ++ix)
      for (int iy = 0; iy < kSide; ++iy)
        if (iy < 24 || iy >= 56) traversable[Index(ix, iy)] = 0;
    return ShortestCellPath(traversable, goal, kSide, kSide, start);
  };
  EXPECT_TRUE(plan(heard).empty()) << "the painted passage is heard narrower than 0.60 m";
  const std::vector<Eigen::Vector2i> path = plan(kept);
  ASSERT_FALSE(path.empty());
  for (const Eigen::Vector2i& c : path) {
    const double x = 0.05 * c.x() + 0.025, y = 0.05 * c.y() + 0.025;
    SCOPED_TRACE(::testing::Message() << x << ", " << y);
    EXPECT_GE(DistanceToBox(x, y, kX0, 1.2, kX1, kSouthTop), 0.25);
    EXPECT_GE(DistanceToBox(x, y, kX0, kNorthBottom, kX1, 2.8), 0.25);
    // Between the boxes it keeps to the centre line (the passage's middle two rows).
    if (x > kX0 && x < kX1) {
      EXPECT_NEAR(y, 2.0, 0.05);
    }
  }
}

TEST(EchoPassageTest, OnePassOrAnEchoNearbyKeepsAHeardCell) {
  std::vector<char> heard(static_cast<std::size_t>(kSide) * kSide, 0);
  heard[Index(40, 40)] = 1;  // passed once only
  heard[Index(20, 40)] = 1;  // passed twice, next to a head-on echo
  BeamFreeGrid beam_free(Geometry(), {});
  // North from (2.02, 1.02) to y 3.0: passes (40, 40) once.
  beam_free.Integrate(Ring(0.5 * kPi, 1.98), {2.02, 1.02, 0.0});
  // North from (1.02, 1.02), echo at y 2.07 (cell (20, 41)): passes (20, 40) twice.
  for (int k = 0; k < 2; ++k) beam_free.Integrate(Ring(0.5 * kPi, 1.05), {1.02, 1.02, 0.0});
  ASSERT_EQ(beam_free.Passes(40, 40), 1);
  ASSERT_EQ(beam_free.Passes(20, 40), 2);
  EXPECT_EQ(HeardWithoutAxisFreePaint(heard, beam_free, 2, 1), heard);
  // Keeping no neighbour: the cell beside the echo goes.
  std::vector<char> expected = heard;
  expected[Index(20, 40)] = 0;
  EXPECT_EQ(HeardWithoutAxisFreePaint(heard, beam_free, 2, 0), expected);
}

TEST(EchoPassageTest, AMaskOfTheWrongSizeThrows) {
  BeamFreeGrid beam_free(Geometry(), {});
  EXPECT_THROW(HeardWithoutAxisFreePaint(std::vector<char>(10, 0), beam_free, 2, 1),
               std::invalid_argument);
}

}  // namespace
}  // namespace plywood::perception
