#include "eval/sonar_map/sonar_ground_truth.h"

namespace plywood::eval {

bool ReachableSpace::IsFree(const Eigen::Vector2d& p_W) const {
  const auto cell = raster->CellAt(p_W);
  if (!cell) return false;
  return free[static_cast<std::size_t>(cell->y()) * raster->width + cell->x()] != 0;
}

ReachableSpace ComputeReachableSpace(const sim::OccupancyRaster& raster,
                                     const Eigen::Vector2d& start_W) {
  ReachableSpace space;
  space.raster = &raster;
  space.free.assign(raster.cells.size(), 0);
  const auto start = raster.CellAt(start_W);
  if (!start || raster.IsOccupied(start->x(), start->y())) return space;
  std::vector<Eigen::Vector2i> stack{*start};
  space.free[static_cast<std::size_t>(start->y()) * raster.width + start->x()] = 1;
  while (!stack.empty()) {
    const Eigen::Vector2i c = stack.back();
    stack.pop_back();
    const Eigen::Vector2i steps[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& s : steps) {
      const Eigen::Vector2i n = c + s;
      if (n.x() < 0 || n.y() < 0 || n.x() >= raster.width || n.y() >= raster.height) continue;
      const std::size_t i = static_cast<std::size_t>(n.y()) * raster.width + n.x();
      if (space.free[i] || raster.IsOccupied(n.x(), n.y())) continue;
      space.free[i] = 1;
      stack.push_back(n);
    }
  }
  return space;
}

}  // namespace plywood::eval
