#include "perception/sonar_map/box_face_sides.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "perception/sonar_map/cell_map_test_support.h"
#include "perception/sonar_map/unknown_share.h"

namespace plywood::perception {
namespace {

// The body's width (the Magellan Pro's 0.2 m radius, twice): the patch's length; its depth more
// than one of these cells.
constexpr double kBodyM = 0.4;
constexpr double kDepthM = 0.1;

RoomSides Sides(const CellMap& map, const Rect& room) {
  return SidesSeenPast(map, TestGrid(), nullptr, 2, room, kBodyM, kDepthM);
}

// Issue 14, generator seed 76 world 26 s3 (docs/sonar_map/history.md, stall76 and round 58b): the
// run ends early in a pocket and the room is fitted with its east side on the west face of a box
// the robot heard, the floor past the box seen free through a gap north of it. The reported room is
// x 0.5-2.0, y 1.0-3.0 (cells x 5-19, y 10-29); the robot saw cells x 5-16, y 10-24 free, the box
// face at the east side (cells x 18-19, y 15-19) and, past it, cells x 20-24, y 20-29: 0.5 m deep,
// 1.0 m along the side. The east side is seen past (and only it): opened to the grid's edge
// (x 4.0) the room holds 700 centres, 460 unknown, where the fitted one holds 300, 110 unknown.
TEST(BoxFaceSidesTest, FloorSeenPastABoxFaceOverTheBodysWidthOpensThatSide) {
  CellMap map = UnknownCells();
  MarkCells(map, 5, 10, 16, 24, CellState::kFree);
  MarkCells(map, 18, 15, 19, 19, CellState::kOccupied);
  MarkCells(map, 20, 20, 24, 29, CellState::kFree);
  const Rect room{0.5, 1.0, 2.0, 3.0};
  const RoomSides sides = Sides(map, room);
  EXPECT_EQ(sides, (RoomSides{false, false, true, false}));
  const Rect open = OpenSides(room, sides, TestGrid());
  EXPECT_EQ(open, (Rect{0.5, 1.0, 4.0, 3.0}));
  EXPECT_DOUBLE_EQ(UnknownShareOfRoom(map, TestGrid(), room), 110.0 / 300.0);
  EXPECT_DOUBLE_EQ(UnknownShareOfRoom(map, TestGrid(), open), 460.0 / 700.0);
}

// A wall heard from the inside: what lies beyond it is stray marks, not floor the body could
// stand on. A line of free cells one cell deep along the whole east wall (the far half of a wall
// read free: not deeper than one cell), a 3 x 3 patch beyond the north side (shorter along it than
// the body's width), a strip beyond the west side 0.4 m deep but broken every third cell, and a
// large patch beyond the south-east corner (outside every side's span) leave the room as fitted;
// round 57c's rule (any free cell beyond a side) opened all but the corner's.
TEST(BoxFaceSidesTest, StrayFreeCellsBeyondAWallLeaveItAWall) {
  CellMap map = UnknownCells();
  const Rect room{0.5, 1.0, 2.0, 3.0};
  MarkCells(map, 5, 10, 19, 29, CellState::kFree);
  MarkCells(map, 20, 10, 20, 29, CellState::kOccupied);  // the east wall's near half
  MarkCells(map, 21, 10, 21, 29, CellState::kFree);      // its far half read free
  MarkCells(map, 10, 31, 12, 33, CellState::kFree);      // 0.3 x 0.3 m beyond the north side
  for (int iy = 10; iy <= 29; ++iy)
    if (iy % 3 != 0) MarkCells(map, 0, iy, 3, iy, CellState::kFree);  // 0.4 m deep, broken along
  MarkCells(map, 25, 0, 35, 8, CellState::kFree);  // beyond the south-east corner
  EXPECT_FALSE(Sides(map, room).Any());
  EXPECT_EQ(OpenSides(room, Sides(map, room), TestGrid()), room);
  // The same north patch grown to the body's width both ways (0.4 x 0.4 m) is floor: north opens.
  MarkCells(map, 10, 31, 13, 34, CellState::kFree);
  EXPECT_EQ(Sides(map, room), (RoomSides{false, false, false, true}));
  EXPECT_EQ(OpenSides(room, Sides(map, room), TestGrid()), (Rect{0.5, 1.0, 2.0, 4.0}));
}

}  // namespace
}  // namespace plywood::perception
