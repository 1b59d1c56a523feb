#include "perception/sonar_map/row_distances.h"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace plywood::perception {

std::vector<int> RowDistancesToNearestSetCell(const std::vector<char>& mask, int width,
                                              int first_row, int last_row, int cap) {
  const int rows = std::max(0, last_row - first_row + 1);
  std::vector<int> distance(static_cast<std::size_t>(rows) * width, cap);
  for (int iy = first_row; iy <= last_row; ++iy) {
    const char* m = mask.data() + static_cast<std::size_t>(iy) * width;
    int* d = distance.data() + static_cast<std::size_t>(iy - first_row) * width;
    // Two sweeps: the nearest set cell to the left, then to the right.
    int last = std::numeric_limits<int>::min() / 2;
    for (int ix = 0; ix < width; ++ix) {
      if (m[ix]) last = ix;
      d[ix] = std::min(cap, ix - last);
    }
    last = std::numeric_limits<int>::max() / 2;
    for (int ix = width - 1; ix >= 0; --ix) {
      if (m[ix]) last = ix;
      d[ix] = std::min(d[ix], std::min(cap, last - ix));
    }
  }
  return distance;
}

}  // namespace plywood::perception
