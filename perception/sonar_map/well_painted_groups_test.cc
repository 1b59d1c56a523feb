#include "perception/sonar_map/well_painted_groups.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "perception/sonar_map/beam_free_test_support.h"

namespace plywood::perception {
namespace {

using Cells = std::vector<Eigen::Vector2i>;
constexpr double kPi = 3.14159265358979323846;

// The cells of columns x0..x1, rows y0..y1, each with `votes`.
void Block(int x0, int x1, int y0, int y1, int votes, Cells& cells, std::vector<int>& counts) {
  for (int iy = y0; iy <= y1; ++iy)
    for (int ix = x0; ix <= x1; ++ix) {
      cells.push_back({ix, iy});
      counts.push_back(votes);
    }
}

TEST(WellPaintedGroupsTest, TwoBoxesJoinedByBlurFromFewReadingsAreApartAndTheBlurGoesToTheNearest) {
  // Box A (columns 2-4) and box B (columns 8-10), rows 5-9, each painted by 20 readings; the gap
  // between them (columns 5-7, more than the 2 cells allowed) painted by 2 far readings. A's east
  // face (column 4) heard head-on from the east, from x 1.45 in the gap's row 7: B lies wholly on
  // that side.
  Cells cells;
  std::vector<int> votes;
  Block(2, 4, 5, 9, 20, cells, votes);
  Block(5, 7, 5, 9, 2, cells, votes);
  Block(8, 10, 5, 9, 20, cells, votes);
  BeamFreeGrid beams = EmptyBeams();
  Hear(beams, {1.45, 0.75}, kPi, 1.0);  // echo at x 0.45, column 4
  const auto sets = ClustersOfWellPaintedCellsHeardApart(cells, votes, 4, 2, beams, 2);
  ASSERT_EQ(sets.size(), 2u);
  // The blur's column 5 lies nearer A, column 7 nearer B, column 6 as near to both (the first
  // well-painted cell met, A's, takes it).
  EXPECT_EQ(sets[0].size(), 5u * 5u);
  EXPECT_EQ(sets[1].size(), 4u * 5u);
  for (const Eigen::Vector2i& c : sets[0]) EXPECT_LE(c.x(), 6) << c.transpose();
  for (const Eigen::Vector2i& c : sets[1]) EXPECT_GE(c.x(), 7) << c.transpose();
  // Every cell once, each set in input order.
  EXPECT_EQ(sets[0].front(), cells.front());
  // Nothing heard from between them: one set, as ClustersHeardApart keeps it.
  const auto unheard = ClustersOfWellPaintedCellsHeardApart(cells, votes, 4, 2, EmptyBeams(), 2);
  ASSERT_EQ(unheard.size(), 1u);
  EXPECT_EQ(unheard[0], cells);
  // Every cell painted by more readings than the blur threshold: the gap is no gap.
  const std::vector<int> all(cells.size(), 20);
  EXPECT_EQ(ClustersOfWellPaintedCellsHeardApart(cells, all, 4, 2, beams, 2).size(), 1u);
  // No cell painted by that many: one set.
  const std::vector<int> few(cells.size(), 3);
  EXPECT_EQ(ClustersOfWellPaintedCellsHeardApart(cells, few, 4, 2, beams, 2).size(), 1u);
}

TEST(WellPaintedGroupsTest, OneBoxWellPaintedOnOppositeFacesOnlyStaysOne) {
  // A box whose west and east faces (columns 5 and 13) were heard from outside many times, its
  // inside and its north and south faces painted by 2 readings: two groups of well-painted cells,
  // but neither face was heard from the side the other lies on.
  Cells cells;
  std::vector<int> votes;
  Block(5, 5, 5, 9, 20, cells, votes);
  Block(6, 12, 5, 9, 2, cells, votes);
  Block(13, 13, 5, 9, 20, cells, votes);
  BeamFreeGrid beams = EmptyBeams();
  Hear(beams, {0.05, 0.75}, 0.0, 0.5);  // west face from the west: echo at x 0.55
  Hear(beams, {1.95, 0.75}, kPi, 0.6);  // east face from the east: echo at x 1.35
  const auto sets = ClustersOfWellPaintedCellsHeardApart(cells, votes, 4, 2, beams, 2);
  ASSERT_EQ(sets.size(), 1u);
  EXPECT_EQ(sets[0], cells);
}

TEST(WellPaintedGroupsTest, AFaceLineBrokenByTwoCellsStaysOneHoweverAnAxisAlongItHeardIt) {
  // One face line (row 5) with columns 7 and 8 missing, heard by an axis running along it from
  // the west whose echo fell in its east part (column 10): with gaps up to 2 cells allowed it is
  // one face; with 1 the east part would lie wholly beyond an echo heard from the west part's side.
  Cells cells;
  std::vector<int> votes;
  Block(2, 6, 5, 5, 20, cells, votes);
  Block(9, 13, 5, 5, 20, cells, votes);
  BeamFreeGrid beams = EmptyBeams();
  Hear(beams, {0.05, 0.55}, 0.0, 1.0);  // echo at x 1.05, column 10
  EXPECT_EQ(ClustersOfWellPaintedCellsHeardApart(cells, votes, 4, 2, beams, 2).size(), 1u);
  EXPECT_EQ(ClustersOfWellPaintedCellsHeardApart(cells, votes, 4, 1, beams, 2).size(), 2u);
}

TEST(WellPaintedGroupsTest, OneCountPerCellAndAPositiveThresholdAreNeeded) {
  const Cells cells{{1, 1}, {2, 2}};
  const BeamFreeGrid beams = EmptyBeams();
  EXPECT_THROW(ClustersOfWellPaintedCellsHeardApart(cells, {5}, 4, 2, beams, 2),
               std::invalid_argument);
  EXPECT_THROW(ClustersOfWellPaintedCellsHeardApart(cells, {5, 5}, 0, 2, beams, 2),
               std::invalid_argument);
}

}  // namespace
}  // namespace plywood::perception
