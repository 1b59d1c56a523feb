#pragma once

#include <vector>

namespace plywood::perception {

// For rows first_row..last_row of a width-wide raster `mask` (row order), each column's distance in
// cells to the nearest set cell of the same row, capped at `cap` (also where the row has none).
// Row first_row's values come first. Within a row the nearest set cell has the least dx^2, so
// these distances give exact nearest-cell distances over a band of rows (Dilate, EscapeCells).
std::vector<int> RowDistancesToNearestSetCell(const std::vector<char>& mask, int width,
                                              int first_row, int last_row, int cap);

}  // namespace plywood::perception
