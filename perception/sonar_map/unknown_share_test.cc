#include "perception/sonar_map/unknown_share.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "perception/sonar_map/cell_map_test_support.h"

namespace plywood::perception {
namespace {

// Issue 14, generator seed 47 world 38 (docs/sonar_map/history.md, round 42a): the robot saw only a
// pocket in one corner of a room whose far walls the sonar had heard, and the run ended
// "map_complete" with most of the reported room unknown. The room here is 3 x 2 m (cells x 5-34,
// y 10-29: 600 centres); the robot saw its east 0.9 m (cells x 26-34): free, with a box face
// heard along its south (y 10-11, occupied). 420 of the 600 cells were never seen: share 0.7.
TEST(UnknownShareTest, ThePartOfTheRoomNeverSeenIsItsUnknownCellsOverItsCells) {
  CellMap map = UnknownCells();
  MarkCells(map, 26, 12, 34, 29, CellState::kFree);
  MarkCells(map, 26, 10, 34, 11, CellState::kOccupied);
  // Seen space outside the room does not count, whatever it holds.
  MarkCells(map, 0, 0, 39, 9, CellState::kFree);
  const Rect room{0.5, 1.0, 3.5, 3.0};
  EXPECT_DOUBLE_EQ(UnknownShareOfRoom(map, TestGrid(), room), 420.0 / 600.0);
  // Once the robot has seen all of it (free or occupied), nothing of the room is unknown.
  MarkCells(map, 5, 10, 25, 29, CellState::kFree);
  MarkCells(map, 5, 10, 9, 14, CellState::kOccupied);
  EXPECT_DOUBLE_EQ(UnknownShareOfRoom(map, TestGrid(), room), 0.0);
}

// A cell counts when its centre lies in the room (the room's sides through cell centres count
// them in, as Rect::Contains does); a room holding no cell centre has no unknown share.
TEST(UnknownShareTest, CellsCountByTheirCentresAndAnEmptyRoomHasNone) {
  const CellMap map = UnknownCells();
  // Centres x 0.55-1.05 (6 cells) by y 0.55-0.65 (2 cells), all unknown.
  EXPECT_DOUBLE_EQ(UnknownShareOfRoom(map, TestGrid(), Rect{0.55, 0.55, 1.05, 0.65}), 1.0);
  EXPECT_DOUBLE_EQ(UnknownShareOfRoom(map, TestGrid(), Rect{0.51, 0.51, 0.54, 0.54}), 0.0);
}

}  // namespace
}  // namespace plywood::perception
