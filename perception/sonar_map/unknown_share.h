#pragma once

#include "perception/sonar_map/frontier_planner.h"
#include "perception/sonar_map/log_odds_grid.h"
#include "perception/sonar_map/partition_map.h"

namespace plywood::perception {

// The share of the grid cells whose centre lies in `room` that are unknown in `cells` (laid out
// as `grid`); 0 when the room holds no cell centre. Issue 14 (docs/sonar_map/history.md, round
// 42a): the end test's measure of how much of the room the robot reports was never seen.
double UnknownShareOfRoom(const CellMap& cells, const LogOddsGrid& grid, const Rect& room);

}  // namespace plywood::perception
