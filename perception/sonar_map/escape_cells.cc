#include "perception/sonar_map/escape_cells.h"

#include <algorithm>
#include <cmath>

#include "perception/sonar_map/row_distances.h"

namespace plywood::perception {

int NearestBlockedDistance2(const std::vector<char>& blocked, int width, int height, int ix, int iy,
                            double radius_cells) {
  const int r = static_cast<int>(std::ceil(radius_cells));
  const double r2 = radius_cells * radius_cells;
  int best = -1;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const int nx = ix + dx, ny = iy + dy, d2 = dx * dx + dy * dy;
      if (nx < 0 || ny < 0 || nx >= width || ny >= height || d2 > r2) continue;
      if (!blocked[static_cast<std::size_t>(ny) * width + nx]) continue;
      if (best < 0 || d2 < best) best = d2;
    }
  return best;
}

std::vector<char> EscapeCells(const std::vector<char>& around, const std::vector<char>& blocked,
                              int width, int height, const Eigen::Vector2i& start,
                              double radius_cells) {
  std::vector<char> out(around.size(), 0);
  if (start.x() < 0 || start.y() < 0 || start.x() >= width || start.y() >= height) return out;
  const int own =
      NearestBlockedDistance2(blocked, width, height, start.x(), start.y(), radius_cells);
  int first_row = height, last_row = -1;
  for (int iy = 0; iy < height; ++iy) {
    const char* a = around.data() + static_cast<std::size_t>(iy) * width;
    if (std::none_of(a, a + width, [](char c) { return c != 0; })) continue;
    first_row = std::min(first_row, iy);
    last_row = iy;
  }
  if (last_row < 0) return out;
  // NearestBlockedDistance2 for every cell of `around` at once: within a row the nearest blocking
  // cell has the least dx^2, so the least dx^2 + dy^2 over the rows within reach is the nearest
  // blocking cell (the same exact integers). Each row's distance to its nearest blocking cell is
  // taken once, for the rows within reach of the cells asked about.
  const int reach = static_cast<int>(
      std::min(std::ceil(radius_cells), static_cast<double>(std::max(width, height))));
  const double reach_squared = radius_cells * radius_cells;
  const int row_lo = std::max(0, first_row - reach),
            row_hi = std::min(height - 1, last_row + reach);
  const std::vector<int> row_distance =
      RowDistancesToNearestSetCell(blocked, width, row_lo, row_hi, reach + 1);
  for (int iy = first_row; iy <= last_row; ++iy)
    for (int ix = 0; ix < width; ++ix) {
      const std::size_t i = static_cast<std::size_t>(iy) * width + ix;
      if (!around[i]) continue;
      int d2 = -1;
      for (int y = std::max(row_lo, iy - reach); y <= std::min(row_hi, iy + reach); ++y) {
        const int dx = row_distance[static_cast<std::size_t>(y - row_lo) * width + ix];
        const int candidate = dx * dx + (y - iy) * (y - iy);
        if (dx <= reach && candidate <= reach_squared && (d2 < 0 || candidate < d2)) d2 = candidate;
      }
      // -1: nothing blocking within the radius, as far as any cell can be.
      out[i] = d2 < 0 || (own >= 0 && d2 >= own);
    }
  return out;
}

}  // namespace plywood::perception
