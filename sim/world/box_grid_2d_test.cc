#include "sim/world/box_grid_2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace plywood::sim {
namespace {

std::vector<int> BruteForce(const std::vector<BoxGrid2D::Box>& boxes, const BoxGrid2D::Box& q) {
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
    const BoxGrid2D::Box& b = boxes[i];
    if (b.lo[0] <= q.hi[0] && q.lo[0] <= b.hi[0] && b.lo[1] <= q.hi[1] && q.lo[1] <= b.hi[1]) {
      out.push_back(i);
    }
  }
  return out;
}

// Random worlds of walls (long thin boxes), small obstacles, points and a few huge boxes, some
// on exact cell boundaries; queries of every size, inside, across and outside the grid, some
// touching a box exactly: the grid returns the brute-force set, in the same order.
TEST(BoxGrid2DTest, QueryGivesTheBruteForceSetOnRandomWorlds) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int queries = 0, nonempty = 0;
  for (int world = 0; world < 40; ++world) {
    const double extent = world % 4 == 0 ? 200.0 : 30.0;
    const double cell = world % 3 == 0 ? 0.37 : world % 3 == 1 ? 1.0 : 4.0;
    const int max_cells = world % 5 == 0 ? 16 : 1 << 20;  // forces coarser cells
    std::vector<BoxGrid2D::Box> boxes;
    const int n = 1 + static_cast<int>(unit(rng) * 600);
    for (int i = 0; i < n; ++i) {
      const double x = (unit(rng) - 0.5) * extent, y = (unit(rng) - 0.5) * extent;
      double hx = 0.0, hy = 0.0;
      switch (i % 5) {
        case 0:  // a wall along x
          hx = 0.5 + 8.0 * unit(rng);
          hy = 0.009;
          break;
        case 1:  // a wall along y
          hx = 0.009;
          hy = 0.5 + 8.0 * unit(rng);
          break;
        case 2:  // a point
          break;
        case 3:  // a huge box now and then
          hx = unit(rng) < 0.02 ? extent : 0.3 * unit(rng);
          hy = 0.3 * unit(rng);
          break;
        default:  // on cell boundaries of the finest grid
          hx = cell * std::floor(3 * unit(rng));
          hy = cell;
      }
      const double cx = i % 5 == 4 ? cell * std::round(x / cell) : x;
      const double cy = i % 5 == 4 ? cell * std::round(y / cell) : y;
      boxes.push_back({{cx - hx, cy - hy}, {cx + hx, cy + hy}});
    }
    const BoxGrid2D grid(boxes, cell, max_cells);
    EXPECT_LE(static_cast<double>(grid.num_cells_x()) * grid.num_cells_y(), max_cells);
    std::vector<int> out;
    for (int k = 0; k < 300; ++k) {
      BoxGrid2D::Box q;
      if (k % 10 == 0) {
        // Exactly touching a box's corner from outside.
        const BoxGrid2D::Box& b = boxes[static_cast<int>(unit(rng) * n) % n];
        q = {{b.hi[0], b.hi[1]}, {b.hi[0] + unit(rng), b.hi[1] + unit(rng)}};
      } else {
        const double x = (unit(rng) - 0.5) * 1.4 * extent, y = (unit(rng) - 0.5) * 1.4 * extent;
        const double h = k % 7 == 0 ? extent * unit(rng) : 2.0 * unit(rng);
        q = {{x - h, y - h * unit(rng)}, {x + h * unit(rng), y + h}};
      }
      grid.Query(q, &out);
      const std::vector<int> expected = BruteForce(boxes, q);
      ASSERT_EQ(out, expected) << "world " << world << " query " << k;
      ++queries;
      nonempty += !expected.empty();
    }
  }
  EXPECT_EQ(queries, 12000);
  EXPECT_GT(nonempty, queries / 4);
}

TEST(BoxGrid2DTest, EmptyGridFindsNothingAndBadArgumentsThrow) {
  const BoxGrid2D empty({}, 1.0);
  std::vector<int> out = {3};
  empty.Query({{-1, -1}, {1, 1}}, &out);
  EXPECT_TRUE(out.empty());
  EXPECT_THROW(BoxGrid2D({}, 0.0), std::invalid_argument);
  EXPECT_THROW(BoxGrid2D({}, 1.0, 0), std::invalid_argument);
  EXPECT_THROW(BoxGrid2D({{{1, 0}, {0, 1}}}, 1.0), std::invalid_argument);
  EXPECT_THROW(BoxGrid2D({{{0, 0}, {INFINITY, 1}}}, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace plywood::sim
