#pragma once

#include <cstddef>
#include <vector>

#include "perception/sonar_map/frontier_planner.h"
#include "perception/sonar_map/log_odds_grid.h"

// A hand-made 4 x 4 m grid for the tests of the rules that read the planning cells (the unknown
// share, the sides seen past).
namespace plywood::perception {

// 10 cm cells from (0, 0). Cell (ix, iy) spans [0.1 ix, 0.1 (ix + 1)] x [0.1 iy, 0.1 (iy + 1)];
// its centre is 5 cm further.
constexpr int kTestGridCells = 40;

inline LogOddsGrid TestGrid() {
  LogOddsGridOptions options;
  options.resolution_m = 0.1;
  options.origin_xy = {0.0, 0.0};
  options.width = options.height = kTestGridCells;
  return LogOddsGrid(options);
}

// Every cell unknown.
inline CellMap UnknownCells() {
  return CellMap{kTestGridCells, kTestGridCells,
                 std::vector<CellState>(static_cast<std::size_t>(kTestGridCells) * kTestGridCells,
                                        CellState::kUnknown)};
}

// Cells ix0..ix1 x iy0..iy1 (inclusive) set to `state`.
inline void MarkCells(CellMap& map, int ix0, int iy0, int ix1, int iy1, CellState state) {
  for (int iy = iy0; iy <= iy1; ++iy)
    for (int ix = ix0; ix <= ix1; ++ix)
      map.cells[static_cast<std::size_t>(iy) * kTestGridCells + ix] = state;
}

}  // namespace plywood::perception
