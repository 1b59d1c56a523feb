#include "perception/sonar_map/cell_dilation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace plywood::perception {
namespace {

// The definition itself: every set cell marks every offset of its disc inside the raster.
std::vector<char> DilateByVisitingEveryOffset(const std::vector<char>& mask, int width, int height,
                                              double radius_cells) {
  std::vector<char> out(mask.size(), 0);
  const int r = static_cast<int>(std::ceil(radius_cells));
  for (int iy = 0; iy < height; ++iy)
    for (int ix = 0; ix < width; ++ix) {
      if (!mask[static_cast<std::size_t>(iy) * width + ix]) continue;
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
          const int nx = ix + dx, ny = iy + dy;
          if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
          if (dx * dx + dy * dy <= radius_cells * radius_cells) {
            out[static_cast<std::size_t>(ny) * width + nx] = 1;
          }
        }
    }
  return out;
}

// Random rasters (sparse dots to solid blobs, thin strips to squares) at the radii the planner
// uses (0.45 m / 0.05 m = 9 cells, 0.35 / 0.05, just under whole numbers) and at the edge cases.
TEST(CellDilationTest, MarksExactlyTheCellsWithinTheRadiusOfASetCell) {
  std::mt19937 rng(7);
  const std::vector<double> radii = {0.0,        0.5, 0.99, 1.0,        1.5,  2.0, std::sqrt(5.0),
                                     3.0 - 1e-9, 7.0, 9.0,  9.0 - 1e-9, 12.5, 40.0};
  int cases = 0;
  for (const int width : {1, 2, 7, 33, 64})
    for (const int height : {1, 3, 17, 50})
      for (const double fill : {0.0, 0.005, 0.05, 0.3, 0.9})
        for (const double radius : radii) {
          std::bernoulli_distribution set(fill);
          std::vector<char> mask(static_cast<std::size_t>(width) * height);
          for (char& c : mask) c = set(rng) ? 1 : 0;
          ASSERT_EQ(Dilate(mask, width, height, radius),
                    DilateByVisitingEveryOffset(mask, width, height, radius))
              << width << " x " << height << ", fill " << fill << ", radius " << radius;
          ++cases;
        }
  EXPECT_EQ(cases, 5 * 4 * 5 * 13);
}

TEST(CellDilationTest, AHugeRadiusMarksTheWholeRasterAndNoRadiusMarksNothing) {
  std::vector<char> mask(6 * 4, 0);
  mask[9] = 1;
  EXPECT_EQ(Dilate(mask, 6, 4, 1e300), std::vector<char>(mask.size(), 1));
  EXPECT_EQ(Dilate(mask, 6, 4, std::nan("")), std::vector<char>(mask.size(), 0));
  EXPECT_EQ(Dilate(mask, 6, 4, -1.0), std::vector<char>(mask.size(), 0));
  EXPECT_EQ(Dilate(std::vector<char>(mask.size(), 0), 6, 4, 3.0),
            std::vector<char>(mask.size(), 0));
}

}  // namespace
}  // namespace plywood::perception
