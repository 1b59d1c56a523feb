#include "perception/sonar_map/frontier_planner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "perception/sonar_map/cell_dilation.h"

namespace plywood::perception {
namespace {

// Pictures are written top row first: rows[iy][ix] is cell (ix, iy).

// '.' free, '#' occupied, '?' unknown.
CellMap Map(const std::vector<std::string>& rows) {
  CellMap map;
  map.height = static_cast<int>(rows.size());
  map.width = static_cast<int>(rows.front().size());
  for (const std::string& row : rows) {
    EXPECT_EQ(static_cast<int>(row.size()), map.width);
    for (const char c : row)
      map.cells.push_back(c == '.'   ? CellState::kFree
                          : c == '#' ? CellState::kOccupied
                                     : CellState::kUnknown);
  }
  return map;
}

// 'x' set, '.' clear.
std::vector<char> Mask(const std::vector<std::string>& rows) {
  std::vector<char> mask;
  for (const std::string& row : rows)
    for (const char c : row) mask.push_back(c == 'x' ? 1 : 0);
  return mask;
}

// The inverse of Mask, so a failing comparison prints a picture.
std::vector<std::string> Picture(const std::vector<char>& mask, int width) {
  std::vector<std::string> rows;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (i % width == 0) rows.emplace_back();
    rows.back() += mask[i] ? 'x' : '.';
  }
  return rows;
}

// Traversable cells of a planning picture: everything but '#'.
std::vector<char> Traversable(const std::vector<std::string>& rows) {
  std::vector<char> mask;
  for (const std::string& row : rows)
    for (const char c : row) mask.push_back(c == '#' ? 0 : 1);
  return mask;
}

// Goal cells of a planning picture: 'G'.
std::vector<char> Goals(const std::vector<std::string>& rows) {
  std::vector<char> mask;
  for (const std::string& row : rows)
    for (const char c : row) mask.push_back(c == 'G' ? 1 : 0);
  return mask;
}

using Cells = std::vector<std::pair<int, int>>;

Cells ToCells(const std::vector<Eigen::Vector2i>& path) {
  Cells out;
  for (const auto& c : path) out.emplace_back(c.x(), c.y());
  return out;
}

std::vector<Eigen::Vector2i> FromCells(const Cells& cells) {
  std::vector<Eigen::Vector2i> out;
  for (const auto& [x, y] : cells) out.emplace_back(x, y);
  return out;
}

Cells Plan(const std::vector<std::string>& rows, Eigen::Vector2i start) {
  const int width = static_cast<int>(rows.front().size()), height = static_cast<int>(rows.size());
  return ToCells(ShortestCellPath(Traversable(rows), Goals(rows), width, height, start));
}

// ---------------------------------------------------------------------------------------------
// FrontierMask

TEST(FrontierMaskTest, MarksExactlyFreeCellsFourAdjacentToUnknown) {
  const CellMap map = Map({
      "..?#.",  //
      ".....",  //
      "#?...",  //
      ".....",  //
  });
  // (3,1), (0,1), (0,3), (2,3) touch an unknown cell only diagonally; (3,0) and (0,2) are
  // occupied; the unknown cells themselves are not frontier.
  EXPECT_EQ(Picture(FrontierMask(map), map.width), (std::vector<std::string>{
                                                       ".x...",  //
                                                       ".xx..",  //
                                                       "..x..",  //
                                                       ".x...",  //
                                                   }));
}

TEST(FrontierMaskTest, OutsideTheRasterIsNotUnknown) {
  const CellMap map = Map({
      "...",  //
      "...",  //
      "...",  //
  });
  EXPECT_EQ(Picture(FrontierMask(map), map.width), (std::vector<std::string>{"...", "...", "..."}));
}

TEST(FrontierMaskTest, DoesNotWrapAcrossRowEnds) {
  // (2,0) and (0,1) are neighbours in memory but not on the map.
  const CellMap map = Map({
      "..?",  //
      "...",  //
      "...",  //
  });
  // (1,0) and (2,1) touch (2,0); (0,1), right after (2,0) in memory, does not.
  EXPECT_EQ(Picture(FrontierMask(map), map.width), (std::vector<std::string>{".x.", "..x", "..."}));
}

// ---------------------------------------------------------------------------------------------
// KeepClusters

TEST(KeepClustersTest, DropsSmallClustersAndKeepsDiagonalOnes) {
  const std::vector<char> mask = Mask({
      "xx....",  //
      "......",  //
      "...x..",  //
      "....x.",  //
      ".....x",  //
      "x.....",  //
  });
  EXPECT_EQ(Picture(KeepClusters(mask, 6, 6, 3), 6), (std::vector<std::string>{
                                                         "......",  //
                                                         "......",  //
                                                         "...x..",  //
                                                         "....x.",  //
                                                         ".....x",  //
                                                         "......",  //
                                                     }));
  EXPECT_EQ(Picture(KeepClusters(mask, 6, 6, 2), 6), (std::vector<std::string>{
                                                         "xx....",  //
                                                         "......",  //
                                                         "...x..",  //
                                                         "....x.",  //
                                                         ".....x",  //
                                                         "......",  //
                                                     }));
  EXPECT_EQ(Picture(KeepClusters(mask, 6, 6, 1), 6), Picture(mask, 6));
  EXPECT_EQ(Picture(KeepClusters(mask, 6, 6, 4), 6), Picture(std::vector<char>(36, 0), 6));
}

TEST(KeepClustersTest, ClustersDoNotWrapAcrossRowEnds) {
  // (2,0), (0,1) and (2,2) would form one 3-cell cluster if row ends wrapped.
  const std::vector<char> mask = Mask({
      "..x",  //
      "x..",  //
      "..x",  //
  });
  EXPECT_EQ(Picture(KeepClusters(mask, 3, 3, 2), 3),
            (std::vector<std::string>{"...", "...", "..."}));
}

TEST(KeepClustersTest, OneCellGapSeparatesClusters) {
  const std::vector<char> mask = Mask({
      "xx.xx",  //
      ".....",  //
      "xx.x.",  //
  });
  // Clusters {(0,0),(1,0)}, {(3,0),(4,0)}, {(0,2),(1,2)}, {(3,2)}: none has 3 cells.
  EXPECT_EQ(Picture(KeepClusters(mask, 5, 3, 3), 5),
            (std::vector<std::string>{".....", ".....", "....."}));
}

// ---------------------------------------------------------------------------------------------
// ClearMask: "closer than" is strict, so a cell at exactly the radius is clear.

const std::vector<std::string> kCentreObstacle = {
    "?....",  //
    ".....",  //
    "..#..",  //
    ".....",  //
    ".....",  //
};

TEST(ClearMaskTest, RadiusOneKeepsTheFourNeighboursAtExactlyOne) {
  const CellMap map = Map(kCentreObstacle);
  // Only free cells: the unknown corner and the occupied cell are never clear.
  EXPECT_EQ(Picture(ClearMask(map, 1.0), 5), (std::vector<std::string>{
                                                 ".xxxx",  //
                                                 "xxxxx",  //
                                                 "xx.xx",  //
                                                 "xxxxx",  //
                                                 "xxxxx",  //
                                             }));
  EXPECT_EQ(Picture(ClearMask(map, 0.0), 5), Picture(ClearMask(map, 1.0), 5));
}

TEST(ClearMaskTest, RadiusJustAboveOneRemovesTheFourNeighbours) {
  const CellMap map = Map(kCentreObstacle);
  EXPECT_EQ(Picture(ClearMask(map, 1.01), 5), (std::vector<std::string>{
                                                  ".xxxx",  //
                                                  "xx.xx",  //
                                                  "x...x",  //
                                                  "xx.xx",  //
                                                  "xxxxx",  //
                                              }));
}

TEST(ClearMaskTest, RadiusSqrtTwoKeepsTheDiagonalsAtExactlySqrtTwo) {
  const CellMap map = Map(kCentreObstacle);
  EXPECT_EQ(Picture(ClearMask(map, std::sqrt(2.0)), 5), (std::vector<std::string>{
                                                            ".xxxx",  //
                                                            "xx.xx",  //
                                                            "x...x",  //
                                                            "xx.xx",  //
                                                            "xxxxx",  //
                                                        }));
}

TEST(ClearMaskTest, RadiusOneAndAHalfRemovesTheEightNeighbours) {
  const CellMap map = Map(kCentreObstacle);
  EXPECT_EQ(Picture(ClearMask(map, 1.5), 5), (std::vector<std::string>{
                                                 ".xxxx",  //
                                                 "x...x",  //
                                                 "x...x",  //
                                                 "x...x",  //
                                                 "xxxxx",  //
                                             }));
  // Distance 2 is not closer than 2.
  EXPECT_EQ(Picture(ClearMask(map, 2.0), 5), Picture(ClearMask(map, 1.5), 5));
}

TEST(ClearMaskTest, RadiusTwoAndAHalfLeavesOnlyTheCorners) {
  const CellMap map = Map(kCentreObstacle);
  // Distances 2 and sqrt 5 are closer than 2.5, the corners (sqrt 8) are not.
  EXPECT_EQ(Picture(ClearMask(map, 2.5), 5), (std::vector<std::string>{
                                                 "....x",  //
                                                 ".....",  //
                                                 ".....",  //
                                                 ".....",  //
                                                 "x...x",  //
                                             }));
}

// ---------------------------------------------------------------------------------------------
// Dilate: "within" is inclusive, so a cell at exactly the radius is marked.

const std::vector<std::string> kDilateSeeds = {
    "x...x",  //
    ".....",  //
    "...x.",  //
    ".....",  //
};

TEST(DilateTest, RadiusOneIsAPlusClippedAtTheBorder) {
  EXPECT_EQ(Picture(Dilate(Mask(kDilateSeeds), 5, 4, 1.0), 5), (std::vector<std::string>{
                                                                   "xx.xx",  //
                                                                   "x..xx",  //
                                                                   "..xxx",  //
                                                                   "...x.",  //
                                                               }));
}

TEST(DilateTest, RadiusOneAndAHalfIsASquare) {
  EXPECT_EQ(Picture(Dilate(Mask(kDilateSeeds), 5, 4, 1.5), 5), (std::vector<std::string>{
                                                                   "xx.xx",  //
                                                                   "xxxxx",  //
                                                                   "..xxx",  //
                                                                   "..xxx",  //
                                                               }));
}

TEST(DilateTest, RadiusZeroAndJustBelowOneChangeNothing) {
  EXPECT_EQ(Picture(Dilate(Mask(kDilateSeeds), 5, 4, 0.0), 5), kDilateSeeds);
  EXPECT_EQ(Picture(Dilate(Mask(kDilateSeeds), 5, 4, 0.99), 5), kDilateSeeds);
}

TEST(DilateTest, RadiusTwoIncludesDistanceTwoButNotSqrtFive) {
  const std::vector<char> seed = Mask({
      ".....",  //
      ".....",  //
      "..x..",  //
      ".....",  //
      ".....",  //
  });
  EXPECT_EQ(Picture(Dilate(seed, 5, 5, 2.0), 5), (std::vector<std::string>{
                                                     "..x..",  //
                                                     ".xxx.",  //
                                                     "xxxxx",  //
                                                     ".xxx.",  //
                                                     "..x..",  //
                                                 }));
}

// ---------------------------------------------------------------------------------------------
// ShortestCellPath: '#' not traversable, 'G' goal, anything else traversable.

TEST(ShortestCellPathTest, FollowsAWindingCorridor) {
  EXPECT_EQ(Plan(
                {
                    ".....",  //
                    "####.",  //
                    ".....",  //
                    ".####",  //
                    "G....",  //
                },
                {0, 0}),
            (Cells{{0, 0},
                   {1, 0},
                   {2, 0},
                   {3, 0},
                   {4, 0},
                   {4, 1},
                   {4, 2},
                   {3, 2},
                   {2, 2},
                   {1, 2},
                   {0, 2},
                   {0, 3},
                   {0, 4}}));
}

TEST(ShortestCellPathTest, TakesTheDiagonalInTheOpen) {
  EXPECT_EQ(Plan(
                {
                    "...",  //
                    "...",  //
                    "..G",  //
                },
                {0, 0}),
            (Cells{{0, 0}, {1, 1}, {2, 2}}));
}

TEST(ShortestCellPathTest, DiagonalNeedsBothSideCells) {
  EXPECT_EQ(Plan({".#", ".G"}, {0, 0}), (Cells{{0, 0}, {0, 1}, {1, 1}}));
  EXPECT_EQ(Plan({"..", "#G"}, {0, 0}), (Cells{{0, 0}, {1, 0}, {1, 1}}));
  EXPECT_EQ(Plan({"..", ".G"}, {0, 0}), (Cells{{0, 0}, {1, 1}}));
}

TEST(ShortestCellPathTest, DiagonalStepsCostSqrtTwo) {
  // Goal (3,3) is three diagonals away (4.24), goal (4,0) four straight steps (4): the straight
  // one is nearer. With diagonals costing 1 it would be (3,3).
  EXPECT_EQ(Plan(
                {
                    ".....",  //
                    ".....",  //
                    ".....",  //
                    "...G.",  //
                },
                {0, 0}),
            (Cells{{0, 0}, {1, 1}, {2, 2}, {3, 3}}));
  EXPECT_EQ(Plan(
                {
                    "....G",  //
                    ".....",  //
                    ".....",  //
                    "...G.",  //
                },
                {0, 0}),
            (Cells{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}}));
}

TEST(ShortestCellPathTest, TiesGoToTheLowerCellIndex) {
  // Around a blocked centre both ways cost 4; the top / left one has the lower indices.
  EXPECT_EQ(Plan({"...", ".#G", "..."}, {0, 1}), (Cells{{0, 1}, {0, 0}, {1, 0}, {2, 0}, {2, 1}}));
  EXPECT_EQ(Plan({"...", "G#.", "..."}, {2, 1}), (Cells{{2, 1}, {2, 0}, {1, 0}, {0, 0}, {0, 1}}));
  EXPECT_EQ(Plan({"...", ".#.", ".G."}, {1, 0}), (Cells{{1, 0}, {0, 0}, {0, 1}, {0, 2}, {1, 2}}));
  // Two goals at the same distance: the one with the lower index.
  EXPECT_EQ(Plan({"G...G"}, {2, 0}), (Cells{{2, 0}, {1, 0}, {0, 0}}));
}

TEST(ShortestCellPathTest, StartOnAGoalIsAOneCellPath) {
  EXPECT_EQ(Plan({"...", ".G.", "..G"}, {1, 1}), (Cells{{1, 1}}));
}

TEST(ShortestCellPathTest, StartNeedNotBeTraversable) {
  const std::vector<std::string> rows = {
      "...",  //
      ".#.",  //
      "..G",  //
  };
  EXPECT_EQ(Plan(rows, {1, 1}), (Cells{{1, 1}, {2, 2}}));
}

TEST(ShortestCellPathTest, EmptyWhenNoGoalIsReachable) {
  EXPECT_EQ(Plan({"..#..", "..#.G", "..#.."}, {0, 0}), Cells{});
  EXPECT_EQ(Plan({"..#", ".#G", "..."}, {0, 0}),
            (Cells{{0, 0}, {0, 1}, {0, 2}, {1, 2}, {2, 2}, {2, 1}}));
  // Closing the bottom leaves only diagonal gaps, which do not count.
  EXPECT_EQ(Plan({"..#", ".#G", "..#"}, {0, 0}), Cells{});
  // No goal at all, and a goal on an untraversable cell (only '#' is untraversable here).
  EXPECT_EQ(Plan({"...", "..."}, {0, 0}), Cells{});
  std::vector<char> goal(6, 0);
  goal[5] = 1;
  std::vector<char> traversable(6, 1);
  traversable[5] = 0;
  EXPECT_TRUE(ShortestCellPath(traversable, goal, 3, 2, {0, 0}).empty());
}

TEST(ShortestCellPathTest, EmptyWhenStartIsOutsideTheRaster) {
  const std::vector<std::string> rows = {"G..", "..."};
  EXPECT_EQ(Plan(rows, {-1, 0}), Cells{});
  EXPECT_EQ(Plan(rows, {3, 0}), Cells{});
  EXPECT_EQ(Plan(rows, {0, 2}), Cells{});
}

// ---------------------------------------------------------------------------------------------
// LineOfSight

TEST(LineOfSightTest, BlockedByAnOccupiedCellBetween) {
  const std::vector<char> row = Traversable({"..#.."});
  EXPECT_FALSE(LineOfSight(row, 5, 1, {0, 0}, {4, 0}));
  EXPECT_FALSE(LineOfSight(row, 5, 1, {4, 0}, {0, 0}));
  EXPECT_TRUE(LineOfSight(row, 5, 1, {0, 0}, {1, 0}));
  EXPECT_TRUE(LineOfSight(row, 5, 1, {3, 0}, {4, 0}));
}

TEST(LineOfSightTest, EndCellsAreNotChecked) {
  const std::vector<char> row = Traversable({"#...#"});
  EXPECT_TRUE(LineOfSight(row, 5, 1, {0, 0}, {4, 0}));
  EXPECT_TRUE(LineOfSight(row, 5, 1, {0, 0}, {0, 0}));
}

TEST(LineOfSightTest, DiagonalAcrossAnOccupiedCell) {
  const std::vector<char> map = Traversable({
      "...",  //
      ".#.",  //
      "...",  //
  });
  EXPECT_FALSE(LineOfSight(map, 3, 3, {0, 0}, {2, 2}));
  EXPECT_FALSE(LineOfSight(map, 3, 3, {2, 0}, {0, 2}));
  EXPECT_FALSE(LineOfSight(map, 3, 3, {0, 0}, {2, 1}));
  EXPECT_TRUE(LineOfSight(map, 3, 3, {0, 0}, {2, 0}));
  EXPECT_TRUE(LineOfSight(map, 3, 3, {0, 0}, {0, 2}));
}

TEST(LineOfSightTest, ShallowSegmentClipsACornerCell) {
  const std::vector<char> map = Traversable({
      ".#.",  //
      "...",  //
  });
  // From (0,0) to (2,1) the segment is at y = 1/3 when x = 2/3: inside cell (1,0).
  EXPECT_FALSE(LineOfSight(map, 3, 2, {0, 0}, {2, 1}));
  EXPECT_TRUE(LineOfSight(map, 3, 2, {0, 1}, {2, 1}));
}

// ---------------------------------------------------------------------------------------------
// SimplifyPath

TEST(SimplifyPathTest, StraightPathKeepsItsEnds) {
  const std::vector<char> map = Traversable({"....."});
  EXPECT_EQ(ToCells(SimplifyPath(FromCells({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}}), map, 5, 1)),
            (Cells{{0, 0}, {4, 0}}));
}

TEST(SimplifyPathTest, LAroundABlockedCornerKeepsTheCorner) {
  const std::vector<std::string> rows = {
      "....",  //
      "###.",  //
      "###.",  //
      "###.",  //
  };
  const Cells path = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}};
  EXPECT_EQ(ToCells(SimplifyPath(FromCells(path), Traversable(rows), 4, 4)),
            (Cells{{0, 0}, {3, 0}, {3, 3}}));
}

TEST(SimplifyPathTest, LInTheOpenBecomesOneSegment) {
  const std::vector<char> map = Traversable({"....", "....", "....", "...."});
  const Cells path = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}};
  EXPECT_EQ(ToCells(SimplifyPath(FromCells(path), map, 4, 4)), (Cells{{0, 0}, {3, 3}}));
}

TEST(SimplifyPathTest, ShortPathsAreReturnedAsTheyAre) {
  const std::vector<char> map = Traversable({"#.#"});
  EXPECT_EQ(ToCells(SimplifyPath({}, map, 3, 1)), Cells{});
  EXPECT_EQ(ToCells(SimplifyPath(FromCells({{1, 0}}), map, 3, 1)), (Cells{{1, 0}}));
  EXPECT_EQ(ToCells(SimplifyPath(FromCells({{0, 0}, {2, 0}}), map, 3, 1)), (Cells{{0, 0}, {2, 0}}));
}

TEST(SimplifyPathTest, WindingCorridorKeepsEveryTurn) {
  const std::vector<std::string> rows = {
      ".....",  //
      "####.",  //
      ".....",  //
      ".####",  //
      "G....",  //
  };
  const std::vector<Eigen::Vector2i> path =
      ShortestCellPath(Traversable(rows), Goals(rows), 5, 5, {0, 0});
  ASSERT_EQ(path.size(), 13u);
  EXPECT_EQ(ToCells(SimplifyPath(path, Traversable(rows), 5, 5)),
            (Cells{{0, 0}, {4, 0}, {4, 2}, {0, 2}, {0, 4}}));
}

}  // namespace
}  // namespace plywood::perception
