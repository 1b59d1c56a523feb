#include "perception/sonar_map/faces_heard_apart.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "perception/sonar_map/beam_free_test_support.h"

namespace plywood::perception {
namespace {

using Cells = std::vector<Eigen::Vector2i>;
constexpr double kPi = 3.14159265358979323846;

// A column of cells x = ix, rows y0..y1.
Cells Column(int ix, int y0, int y1) {
  Cells cells;
  for (int iy = y0; iy <= y1; ++iy) cells.push_back({ix, iy});
  return cells;
}

TEST(EchoesFacingTest, CountsEchoesWhoseTransducerStoodOnTheOtherGroupsSide) {
  // A face at column 10 (x 1.0-1.1, rows 5-9), heard head-on from the west (x 0.45, pointing
  // east: echo at x 1.05) and from the east (x 1.65, pointing west: echo at x 1.05).
  const Cells face = Column(10, 5, 9);
  BeamFreeGrid from_west = EmptyBeams(), from_east = EmptyBeams();
  Hear(from_west, {0.45, 0.75}, 0.0, 0.60, 3);
  Hear(from_east, {1.65, 0.75}, kPi, 0.60, 3);
  // Another group wholly west of the face (column 3): the robot stood on its side only when it
  // heard the face from the west.
  const Cells west = Column(3, 5, 9);
  EXPECT_EQ(EchoesFacing(face, west, from_west), 3);
  EXPECT_EQ(EchoesFacing(face, west, from_east), 0);
  // A group east of the face: the other way round.
  const Cells east = Column(16, 5, 9);
  EXPECT_EQ(EchoesFacing(face, east, from_west), 0);
  EXPECT_EQ(EchoesFacing(face, east, from_east), 3);
  // Within a cell of the echo's cell (the range noise) or reaching past it: not wholly in front.
  EXPECT_EQ(EchoesFacing(face, Column(9, 0, 2), from_west), 0);
  EXPECT_EQ(EchoesFacing(face, Column(8, 0, 2), from_west), 3);
  EXPECT_EQ(EchoesFacing(face, Cells{{3, 0}, {12, 0}}, from_west), 0);
  // Axes along y (from the south) say nothing about a group west of the face.
  BeamFreeGrid from_south = EmptyBeams();
  Hear(from_south, {1.05, 0.15}, 0.5 * kPi, 0.40, 3);
  EXPECT_EQ(EchoesFacing(face, west, from_south), 0);
  EXPECT_EQ(EchoesFacing(face, Column(3, 0, 2), from_south), 3);
  EXPECT_EQ(EchoesFacing(face, {}, from_west), 0);
}

TEST(ClustersHeardApartTest, OneBoxHeardOnOppositeFacesStaysOneTwoBoxesFacingAreApart) {
  // Two faces 0.6 m apart (columns 4 and 11, rows 5-9), unknown between: more than the gap apart.
  Cells cells = Column(4, 5, 9);
  const Cells second = Column(11, 5, 9);
  cells.insert(cells.end(), second.begin(), second.end());
  // One box seen from two sides: the west face heard from the west, the east face from the east;
  // the other face lies behind each.
  BeamFreeGrid outside = EmptyBeams();
  Hear(outside, {0.05, 0.75}, 0.0, 0.40);
  Hear(outside, {1.65, 0.75}, kPi, 0.50);
  const auto one = ClustersHeardApart(cells, 2, outside, 2);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0], cells);
  // Two boxes: the west one's east face (column 4) heard from the east, from where the second
  // lies. The second's own faces were heard from outside.
  BeamFreeGrid between = EmptyBeams();
  Hear(between, {1.05, 0.55}, kPi, 0.60);
  Hear(between, {1.65, 0.75}, kPi, 0.50);
  const auto two = ClustersHeardApart(cells, 2, between, 2);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0], Column(4, 5, 9));
  EXPECT_EQ(two[1], second);
  // One echo is too few (min_echoes 2).
  BeamFreeGrid once = EmptyBeams();
  Hear(once, {1.05, 0.55}, kPi, 0.60, 1);
  EXPECT_EQ(ClustersHeardApart(cells, 2, once, 2).size(), 1u);
  // Within the gap: one group whatever was heard.
  EXPECT_EQ(ClustersHeardApart(cells, 6, between, 2).size(), 1u);
  EXPECT_TRUE(ClustersHeardApart({}, 2, between, 2).empty());
  EXPECT_THROW(ClustersHeardApart(cells, 2, between, 0), std::invalid_argument);
}

TEST(ClustersHeardApartTest, GroupsNotHeardApartJoinTheFirstSetTheyMayKeepingTheCellsOrder) {
  // Three faces in a row along x (columns 2, 9, 16): the middle one heard from the west, from
  // where the first lies, so those two are apart; nothing was heard between the first and the
  // third, so they are one set, its cells in input order.
  const Cells a = Column(2, 5, 7), b = Column(9, 5, 7), c = Column(16, 5, 7);
  Cells cells;
  for (const Cells* g : {&a, &c, &b}) cells.insert(cells.end(), g->begin(), g->end());
  BeamFreeGrid beams = EmptyBeams();
  Hear(beams, {0.45, 0.65}, 0.0, 0.50);
  const auto sets = ClustersHeardApart(cells, 2, beams, 2);
  ASSERT_EQ(sets.size(), 2u);
  Cells ac = a;
  ac.insert(ac.end(), c.begin(), c.end());
  EXPECT_EQ(sets[0], ac);
  EXPECT_EQ(sets[1], b);
}

}  // namespace
}  // namespace plywood::perception
