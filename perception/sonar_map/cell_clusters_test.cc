#include "perception/sonar_map/cell_clusters.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace plywood::perception {
namespace {

using Cells = std::vector<Eigen::Vector2i>;

TEST(ClustersWithinGapTest, CellsUpToTheGapApartAlongBothAxesAreOneGroup) {
  // Two runs of cells along x, 3 cells apart (x 0-2 and x 6-8), and one cell diagonally 2 away.
  const Cells cells{{0, 0}, {1, 0}, {2, 0}, {6, 0}, {7, 0}, {8, 0}, {10, 2}};
  const auto eight_connected = ClustersWithinGap(cells, 0);
  ASSERT_EQ(eight_connected.size(), 3u);
  EXPECT_EQ(eight_connected[0], (Cells{{0, 0}, {1, 0}, {2, 0}}));
  EXPECT_EQ(eight_connected[1], (Cells{{6, 0}, {7, 0}, {8, 0}}));
  EXPECT_EQ(eight_connected[2], (Cells{{10, 2}}));
  // A gap of one cell joins (8, 0) and (10, 2); three cells lie between x 2 and 6.
  const auto one = ClustersWithinGap(cells, 1);
  ASSERT_EQ(one.size(), 2u);
  EXPECT_EQ(one[1], (Cells{{6, 0}, {7, 0}, {8, 0}, {10, 2}}));
  EXPECT_EQ(ClustersWithinGap(cells, 3).size(), 1u);
  EXPECT_EQ(ClustersWithinGap(cells, 3)[0], cells);
}

TEST(ClustersWithinGapTest, ARepeatedCellGoesWithItsFirstCopy) {
  const auto groups = ClustersWithinGap({{0, 0}, {5, 0}, {0, 0}}, 1);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0], (Cells{{0, 0}, {0, 0}}));
  EXPECT_EQ(groups[1], (Cells{{5, 0}}));
}

TEST(ClustersWithinGapTest, EmptyInputGivesNoGroupAndANegativeGapThrows) {
  EXPECT_TRUE(ClustersWithinGap({}, 2).empty());
  EXPECT_THROW(ClustersWithinGap({{0, 0}}, -1), std::invalid_argument);
}

}  // namespace
}  // namespace plywood::perception
