#include "perception/sonar_map/cell_clusters.h"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

namespace plywood::perception {

std::vector<std::vector<Eigen::Vector2i>> ClustersWithinGap(
    const std::vector<Eigen::Vector2i>& cells, int max_gap) {
  if (max_gap < 0) throw std::invalid_argument("max_gap: must be >= 0");
  std::vector<std::vector<Eigen::Vector2i>> groups;
  if (cells.empty()) return groups;
  Eigen::Vector2i lo = cells.front(), hi = cells.front();
  for (const Eigen::Vector2i& c : cells) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
  const int width = hi.x() - lo.x() + 1, height = hi.y() - lo.y() + 1;
  // Index of each cell in `cells` (the first, for repeated cells), -1 where none.
  std::vector<int> at(static_cast<std::size_t>(width) * height, -1);
  auto slot = [&](int x, int y) -> int& {
    return at[static_cast<std::size_t>(y - lo.y()) * width + (x - lo.x())];
  };
  for (std::size_t i = 0; i < cells.size(); ++i) {
    int& s = slot(cells[i].x(), cells[i].y());
    if (s < 0) s = static_cast<int>(i);
  }
  std::vector<int> group_of(cells.size(), -1);
  const int reach = max_gap + 1;
  for (std::size_t first = 0; first < cells.size(); ++first) {
    // A repeated cell goes with its first copy (below).
    if (group_of[first] >= 0 || slot(cells[first].x(), cells[first].y()) != static_cast<int>(first))
      continue;
    const int id = static_cast<int>(groups.size());
    std::vector<int> stack{static_cast<int>(first)};
    group_of[first] = id;
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      const Eigen::Vector2i c = cells[static_cast<std::size_t>(i)];
      for (int y = std::max(lo.y(), c.y() - reach); y <= std::min(hi.y(), c.y() + reach); ++y)
        for (int x = std::max(lo.x(), c.x() - reach); x <= std::min(hi.x(), c.x() + reach); ++x) {
          const int j = slot(x, y);
          if (j < 0 || group_of[static_cast<std::size_t>(j)] >= 0) continue;
          group_of[static_cast<std::size_t>(j)] = id;
          stack.push_back(j);
        }
    }
    groups.emplace_back();
  }
  // Repeated cells join the group of their first copy; keep input order within each group.
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const int g = group_of[i] >= 0
                      ? group_of[i]
                      : group_of[static_cast<std::size_t>(slot(cells[i].x(), cells[i].y()))];
    groups[static_cast<std::size_t>(g)].push_back(cells[i]);
  }
  return groups;
}

}  // namespace plywood::perception
