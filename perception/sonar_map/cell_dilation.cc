#include "perception/sonar_map/cell_dilation.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "perception/sonar_map/row_distances.h"

namespace plywood::perception {

std::vector<char> Dilate(const std::vector<char>& mask, int width, int height,
                         double radius_cells) {
  std::vector<char> out(mask.size(), 0);
  if (width <= 0 || height <= 0 || !(radius_cells >= 0.0)) return out;
  // A row offset dy reaches the columns |dx| <= half_width[dy]: the largest dx with
  // dx^2 + dy^2 <= radius^2, the same integer test as visiting every offset of the disc;
  // -1 when the row is out of reach. The set is contiguous because dx^2 grows with |dx|.
  // Offsets beyond the raster reach no cell of it (and a huge radius must not overflow an int).
  const int reach = static_cast<int>(
      std::min(std::ceil(radius_cells), static_cast<double>(std::max(width, height))));
  const double reach_squared = radius_cells * radius_cells;
  std::vector<int> half_width(2 * reach + 1, -1);
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = reach; dx >= 0; --dx) {
      if (dx * dx + dy * dy <= reach_squared) {
        half_width[dy + reach] = dx;
        break;
      }
    }
  }
  // Per row, each column's distance to the nearest set cell of the same row (capped: anything
  // beyond `reach` is out of reach alike).
  const std::vector<int> row_distance =
      RowDistancesToNearestSetCell(mask, width, 0, height - 1, reach + 1);
  std::vector<char> row_has_set(height, 0);
  for (int iy = 0; iy < height; ++iy) {
    const char* m = mask.data() + static_cast<std::size_t>(iy) * width;
    row_has_set[iy] = std::any_of(m, m + width, [](char c) { return c != 0; });
  }
  // A cell is marked when some row within reach has a set cell within that row's half width.
  for (int iy = 0; iy < height; ++iy) {
    char* o = out.data() + static_cast<std::size_t>(iy) * width;
    for (int dy = -reach; dy <= reach; ++dy) {
      const int source = iy - dy;
      const int w = half_width[dy + reach];
      if (source < 0 || source >= height || w < 0 || !row_has_set[source]) continue;
      const int* d = row_distance.data() + static_cast<std::size_t>(source) * width;
      for (int ix = 0; ix < width; ++ix) o[ix] |= static_cast<char>(d[ix] <= w);
    }
  }
  return out;
}

}  // namespace plywood::perception
