#include "perception/sonar_map/row_distances.h"

#include <gtest/gtest.h>

#include <vector>

namespace plywood::perception {
namespace {

TEST(RowDistancesTest, EachColumnGetsItsDistanceToTheRowsNearestSetCellCapped) {
  // Rows of 7: "x.....x", ".......", "..x...." (any non-zero value is set).
  std::vector<char> mask(21, 0);
  mask[0] = 1;
  mask[6] = 2;
  mask[16] = 1;
  EXPECT_EQ(RowDistancesToNearestSetCell(mask, 7, 0, 2, 4),
            (std::vector<int>{0, 1, 2, 3, 2, 1, 0,  //
                              4, 4, 4, 4, 4, 4, 4,  //
                              2, 1, 0, 1, 2, 3, 4}));
  // A band of rows: row 2 alone, and no rows at all.
  EXPECT_EQ(RowDistancesToNearestSetCell(mask, 7, 2, 2, 3),
            (std::vector<int>{2, 1, 0, 1, 2, 3, 3}));
  EXPECT_TRUE(RowDistancesToNearestSetCell(mask, 7, 2, 1, 3).empty());
}

}  // namespace
}  // namespace plywood::perception
