#include "perception/sonar_map/escape_cells.h"

#include <cmath>

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
  for (int iy = 0; iy < height; ++iy)
    for (int ix = 0; ix < width; ++ix) {
      const std::size_t i = static_cast<std::size_t>(iy) * width + ix;
      if (!around[i]) continue;
      const int d2 = NearestBlockedDistance2(blocked, width, height, ix, iy, radius_cells);
      // -1: nothing blocking within the radius, as far as any cell can be.
      out[i] = d2 < 0 || (own >= 0 && d2 >= own);
    }
  return out;
}

}  // namespace plywood::perception
