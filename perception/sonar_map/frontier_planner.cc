#include "perception/sonar_map/frontier_planner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <utility>

#include "perception/sonar_map/cell_dilation.h"

namespace plywood::perception {
namespace {

std::size_t Index(int ix, int iy, int width) { return static_cast<std::size_t>(iy) * width + ix; }

}  // namespace

std::vector<char> FrontierMask(const CellMap& map) {
  std::vector<char> mask(map.cells.size(), 0);
  constexpr int kDx[4] = {1, -1, 0, 0}, kDy[4] = {0, 0, 1, -1};
  for (int iy = 0; iy < map.height; ++iy)
    for (int ix = 0; ix < map.width; ++ix) {
      if (map.At(ix, iy) != CellState::kFree) continue;
      for (int k = 0; k < 4; ++k) {
        const int nx = ix + kDx[k], ny = iy + kDy[k];
        if (map.Contains(nx, ny) && map.At(nx, ny) == CellState::kUnknown) {
          mask[Index(ix, iy, map.width)] = 1;
          break;
        }
      }
    }
  return mask;
}

std::vector<char> KeepClusters(const std::vector<char>& mask, int width, int height,
                               int min_cells) {
  std::vector<char> out(mask.size(), 0), seen(mask.size(), 0);
  for (int iy = 0; iy < height; ++iy)
    for (int ix = 0; ix < width; ++ix) {
      if (!mask[Index(ix, iy, width)] || seen[Index(ix, iy, width)]) continue;
      std::vector<Eigen::Vector2i> cluster, stack{{ix, iy}};
      seen[Index(ix, iy, width)] = 1;
      while (!stack.empty()) {
        const Eigen::Vector2i c = stack.back();
        stack.pop_back();
        cluster.push_back(c);
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = c.x() + dx, ny = c.y() + dy;
            if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
            const std::size_t i = Index(nx, ny, width);
            if (!mask[i] || seen[i]) continue;
            seen[i] = 1;
            stack.push_back({nx, ny});
          }
      }
      if (static_cast<int>(cluster.size()) < min_cells) continue;
      for (const auto& c : cluster) out[Index(c.x(), c.y(), width)] = 1;
    }
  return out;
}

std::vector<char> ClearMask(const CellMap& map, double radius_cells) {
  std::vector<char> occupied(map.cells.size(), 0);
  for (std::size_t i = 0; i < map.cells.size(); ++i)
    occupied[i] = map.cells[i] == CellState::kOccupied;
  // Dilate marks distances <= r; "closer than r" is strict, so shrink r by a hair.
  const std::vector<char> near =
      Dilate(occupied, map.width, map.height, std::max(0.0, radius_cells - 1e-9));
  std::vector<char> clear(map.cells.size(), 0);
  for (std::size_t i = 0; i < map.cells.size(); ++i)
    clear[i] = map.cells[i] == CellState::kFree && !near[i];
  return clear;
}

std::vector<Eigen::Vector2i> ShortestCellPath(const std::vector<char>& traversable,
                                              const std::vector<char>& goal, int width, int height,
                                              const Eigen::Vector2i& start) {
  if (start.x() < 0 || start.y() < 0 || start.x() >= width || start.y() >= height) return {};
  const std::size_t n = static_cast<std::size_t>(width) * height;
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<long> parent(n, -1);
  using Item = std::pair<double, long>;  // (distance, cell index): ties go to the lower index
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  const long s = static_cast<long>(Index(start.x(), start.y(), width));
  dist[s] = 0.0;
  queue.push({0.0, s});
  auto ok = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < width && y < height && traversable[Index(x, y, width)];
  };
  while (!queue.empty()) {
    const auto [d, i] = queue.top();
    queue.pop();
    if (d > dist[i]) continue;
    const int ix = static_cast<int>(i % width), iy = static_cast<int>(i / width);
    if (goal[i]) {
      std::vector<Eigen::Vector2i> path;
      for (long k = i; k >= 0; k = parent[k])
        path.push_back({static_cast<int>(k % width), static_cast<int>(k / width)});
      std::reverse(path.begin(), path.end());
      return path;
    }
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0) continue;
        const int nx = ix + dx, ny = iy + dy;
        if (!ok(nx, ny)) continue;
        if (dx != 0 && dy != 0 && !(ok(ix + dx, iy) && ok(ix, iy + dy))) continue;
        const double nd = d + ((dx != 0 && dy != 0) ? std::sqrt(2.0) : 1.0);
        const long j = static_cast<long>(Index(nx, ny, width));
        if (nd < dist[j]) {
          dist[j] = nd;
          parent[j] = i;
          queue.push({nd, j});
        }
      }
  }
  return {};
}

bool LineOfSight(const std::vector<char>& traversable, int width, int height,
                 const Eigen::Vector2i& a, const Eigen::Vector2i& b) {
  const Eigen::Vector2d d = (b - a).cast<double>();
  const int steps = static_cast<int>(std::ceil(4.0 * d.norm()));
  for (int k = 1; k < steps; ++k) {
    const Eigen::Vector2d p = a.cast<double>() + d * (static_cast<double>(k) / steps);
    const int x = static_cast<int>(std::lround(p.x())), y = static_cast<int>(std::lround(p.y()));
    if ((x == a.x() && y == a.y()) || (x == b.x() && y == b.y())) continue;
    if (x < 0 || y < 0 || x >= width || y >= height || !traversable[Index(x, y, width)])
      return false;
  }
  return true;
}

std::vector<Eigen::Vector2i> SimplifyPath(const std::vector<Eigen::Vector2i>& path,
                                          const std::vector<char>& traversable, int width,
                                          int height) {
  if (path.size() <= 2) return path;
  std::vector<Eigen::Vector2i> out{path.front()};
  std::size_t from = 0;
  while (from + 1 < path.size()) {
    // The farthest cell still in sight of the last kept one.
    std::size_t next = from + 1;
    for (std::size_t k = path.size() - 1; k > from + 1; --k)
      if (LineOfSight(traversable, width, height, path[from], path[k])) {
        next = k;
        break;
      }
    out.push_back(path[next]);
    from = next;
  }
  return out;
}

}  // namespace plywood::perception
