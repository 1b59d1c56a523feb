#pragma once

#include <vector>

namespace plywood::perception {

// Marks every cell whose centre lies within radius_cells (Euclidean, in cells, inclusive) of a set
// cell of `mask`, a width x height raster in row order. The planner dilates its 160 x 160 grids a
// few hundred times a run, so the cost is (2 ceil(radius) + 1) passes over the raster whatever
// the number of set cells.
std::vector<char> Dilate(const std::vector<char>& mask, int width, int height, double radius_cells);

}  // namespace plywood::perception
