#include "eval/sonar_map/sonar_ground_truth.h"

#include <algorithm>
#include <stdexcept>

#include "sim/config/config_error.h"
#include "sim/runner/format_number.h"
#include "sim/world/ground_truth_walls.h"

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

void OccupancyTruth::FitScoredBox() {
  x0 = raster.width;
  y0 = raster.height;
  x1 = y1 = -1;
  for (int iy = 0; iy < raster.height; ++iy)
    for (int ix = 0; ix < raster.width; ++ix)
      if (CellFree(ix, iy)) {
        x0 = std::min(x0, ix);
        x1 = std::max(x1, ix);
        y0 = std::min(y0, iy);
        y1 = std::max(y1, iy);
      }
}

std::optional<Eigen::Vector2d> OccupancyTruth::ReachableCellOnTheEdge() const {
  if (x1 < x0) return std::nullopt;
  for (int iy = y0; iy <= y1; ++iy)
    for (int ix = x0; ix <= x1; ++ix) {
      const bool edge = ix == 0 || iy == 0 || ix == raster.width - 1 || iy == raster.height - 1;
      if (edge && CellFree(ix, iy)) return raster.CellCentre(ix, iy);
    }
  return std::nullopt;
}

std::unique_ptr<OccupancyTruth> MakeOccupancyTruth(const mjModel* model,
                                                   const Eigen::Vector2d& start_W,
                                                   const std::string& spawn_source) {
  // The raster spans the world's upright geoms; a world of nothing but a floor has no extent (was
  // "plywood: bounds_W: unset ...", naming neither the file nor the world).
  if (sim::ExtractUprightGeoms(model).empty()) {
    throw sim::ConfigError(spawn_source, "world",
                           "the world holds no wall or obstacle (no upright box, cylinder, capsule "
                           "or sphere at any height): there is no room to score a map of");
  }
  auto truth = std::make_unique<OccupancyTruth>();
  sim::OccupancyRasterOptions options;
  options.resolution_m = sim::kOccupancyTruthResolutionM;
  try {
    truth->raster = sim::RasteriseOccupancy(model, options);
  } catch (const std::invalid_argument& e) {  // a world too wide for its cells
    throw sim::ConfigError(spawn_source, "world", e.what());
  }
  truth->space = ComputeReachableSpace(truth->raster, start_W);
  truth->FitScoredBox();
  if (truth->x1 < truth->x0) {
    throw sim::ConfigError(spawn_source, "robot.spawn",
                           "(" + sim::FormatNumber(start_W.x()) + ", " +
                               sim::FormatNumber(start_W.y()) +
                               ") is not in free space: no reachable area to score a map against");
  }
  return truth;
}

OccupancyError ScoreOccupancy(const OccupancyTruth& truth,
                              const std::function<bool(const Eigen::Vector2d&)>& map_says_free) {
  OccupancyError error;
  error.cell_area_m2 = truth.raster.resolution_m * truth.raster.resolution_m;
  for (int iy = truth.y0; iy <= truth.y1; ++iy)
    for (int ix = truth.x0; ix <= truth.x1; ++ix) {
      if (!truth.unscored.empty() &&
          truth.unscored[static_cast<std::size_t>(iy) * truth.raster.width + ix]) {
        continue;
      }
      const bool free = truth.CellFree(ix, iy);
      error.total_cells += free;
      error.error_cells += free != map_says_free(truth.raster.CellCentre(ix, iy));
    }
  return error;
}

}  // namespace plywood::eval
