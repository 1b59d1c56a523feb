#include "eval/sonar_map/narrow_gaps.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace plywood::eval {
namespace {

// For each cell, how many of the `window` cells ending at it (along a row, or a column with
// stride `width`) hold a non-zero value; computed with a running sum, so O(cells) whatever the
// window.
std::vector<int> TrailingWindowCounts(const std::vector<char>& values, int width, int height,
                                      int window, bool along_rows) {
  std::vector<int> counts(values.size(), 0);
  const int lines = along_rows ? height : width;
  const int length = along_rows ? width : height;
  for (int line = 0; line < lines; ++line) {
    int sum = 0;
    for (int k = 0; k < length; ++k) {
      const auto at = [&](int position) {
        return along_rows ? static_cast<std::size_t>(line) * width + position
                          : static_cast<std::size_t>(position) * width + line;
      };
      sum += values[at(k)] != 0;
      if (k >= window) sum -= values[at(k - window)] != 0;
      counts[at(k)] = sum;
    }
  }
  return counts;
}

}  // namespace

std::vector<char> CellsASquareCovers(const std::vector<char>& set, int width, int height,
                                     int side_cells) {
  if (side_cells < 1) throw std::invalid_argument("CellsASquareCovers: side_cells must be >= 1");
  const std::size_t n = static_cast<std::size_t>(width) * height;
  if (set.size() != n) throw std::invalid_argument("CellsASquareCovers: set is not width x height");
  // Squares named by their highest cell (x, y): the square [x - k + 1, x] x [y - k + 1, y] lies in
  // the set when each of its k rows has k set cells ending at column x.
  const int k = side_cells;
  std::vector<int> row = TrailingWindowCounts(set, width, height, k, true);
  std::vector<char> row_full(n, 0);
  for (std::size_t i = 0; i < n; ++i) row_full[i] = row[i] == k;
  const std::vector<int> column = TrailingWindowCounts(row_full, width, height, k, false);
  std::vector<char> square(n, 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      // A square fits only where it lies wholly inside the grid.
      square[i] = x >= k - 1 && y >= k - 1 && column[i] == k;
    }
  // A cell is covered when a square named by a cell in [x, x + k - 1] x [y, y + k - 1] fits:
  // the same trailing windows, read from the far corner.
  std::vector<char> flipped(n, 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      flipped[static_cast<std::size_t>(height - 1 - y) * width + (width - 1 - x)] =
          square[static_cast<std::size_t>(y) * width + x];
  row = TrailingWindowCounts(flipped, width, height, k, true);
  std::vector<char> row_any(n, 0);
  for (std::size_t i = 0; i < n; ++i) row_any[i] = row[i] > 0;
  const std::vector<int> any = TrailingWindowCounts(row_any, width, height, k, false);
  std::vector<char> covered(n, 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      covered[static_cast<std::size_t>(y) * width + x] =
          any[static_cast<std::size_t>(height - 1 - y) * width + (width - 1 - x)] > 0;
  return covered;
}

std::unique_ptr<OccupancyTruth> MakeTruthWithoutNarrowGaps(const OccupancyTruth& truth,
                                                           double body_width_m) {
  if (!(body_width_m > 0.0) || !std::isfinite(body_width_m)) {
    throw std::invalid_argument("MakeTruthWithoutNarrowGaps: body_width_m must be > 0");
  }
  auto wide = std::make_unique<OccupancyTruth>();
  wide->raster = truth.raster;
  wide->space = truth.space;
  wide->space.raster = &wide->raster;
  wide->x0 = truth.x0;
  wide->y0 = truth.y0;
  wide->x1 = truth.x1;
  wide->y1 = truth.y1;
  const sim::OccupancyRaster& raster = truth.raster;
  // The body fits in a gap of its own width: a square of that many cells (rounded up) must fit.
  const int side =
      std::max(1, static_cast<int>(std::ceil(body_width_m / raster.resolution_m - 1e-9)));
  const std::vector<char> covered =
      CellsASquareCovers(truth.space.free, raster.width, raster.height, side);
  wide->unscored = truth.unscored.empty() ? std::vector<char>(covered.size(), 0) : truth.unscored;
  for (std::size_t i = 0; i < covered.size(); ++i)
    if (truth.space.free[i] && !covered[i]) wide->unscored[i] = 1;
  return wide;
}

}  // namespace plywood::eval
