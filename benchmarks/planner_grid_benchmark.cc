// The sonar explorer's grid kernels on its own raster (160 x 160 cells of 5 cm): the clearance
// dilation the planner runs a few hundred times a seed 001 run, and the escape cells around a robot
// standing too close to something.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "perception/sonar_map/cell_dilation.h"
#include "perception/sonar_map/escape_cells.h"

namespace plywood::perception {
namespace {

constexpr int kCells = 160;

// A 3.2 x 3.6 m room's walls, two cells thick, and a 0.6 x 0.4 m box inside it.
std::vector<char> RoomWithABox() {
  std::vector<char> mask(static_cast<std::size_t>(kCells) * kCells, 0);
  const auto set = [&](int ix, int iy) { mask[static_cast<std::size_t>(iy) * kCells + ix] = 1; };
  const int x0 = 48, x1 = 48 + 64, y0 = 44, y1 = 44 + 72;
  for (int t = 0; t < 2; ++t) {
    for (int ix = x0; ix <= x1; ++ix) {
      set(ix, y0 + t);
      set(ix, y1 - t);
    }
    for (int iy = y0; iy <= y1; ++iy) {
      set(x0 + t, iy);
      set(x1 - t, iy);
    }
  }
  for (int iy = 60; iy < 68; ++iy)
    for (int ix = 90; ix < 102; ++ix) set(ix, iy);
  return mask;
}

void BM_DilateByThePathClearance(benchmark::State& state) {
  const std::vector<char> mask = RoomWithABox();
  for (auto _ : state) {
    std::vector<char> near = Dilate(mask, kCells, kCells, 0.45 / 0.05);
    benchmark::DoNotOptimize(near.data());
  }
  state.SetItemsProcessed(state.iterations());  // dilations
}
BENCHMARK(BM_DilateByThePathClearance);

void BM_EscapeCellsBesideTheBox(benchmark::State& state) {
  const std::vector<char> heard = RoomWithABox();
  const Eigen::Vector2i start(84, 64);  // 0.3 m west of the box
  std::vector<char> around(heard.size(), 0);
  for (int iy = 0; iy < kCells; ++iy)
    for (int ix = 0; ix < kCells; ++ix)
      around[static_cast<std::size_t>(iy) * kCells + ix] =
          std::hypot(ix - start.x(), iy - start.y()) < 9.0;
  for (auto _ : state) {
    std::vector<char> escape = EscapeCells(around, heard, kCells, kCells, start, 9.0);
    benchmark::DoNotOptimize(escape.data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EscapeCellsBesideTheBox);

}  // namespace
}  // namespace plywood::perception
