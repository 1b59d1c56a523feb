#pragma once

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/world/occupancy_raster.h"

namespace plywood::eval {

// Ground truth for seed 001's occupancy maps: the free space the robot can reach (4-connected
// flood fill of the raster's free cells from `start`). Everything else (walls, obstacles, and the
// space behind walls) counts as "not free"; the seed's maps label it the same way.
struct ReachableSpace {
  const sim::OccupancyRaster* raster = nullptr;
  std::vector<char> free;  // by raster cell
  bool IsFree(const Eigen::Vector2d& p_W) const;
};

ReachableSpace ComputeReachableSpace(const sim::OccupancyRaster& raster,
                                     const Eigen::Vector2d& start_W);

// What seed 001's maps are scored against: the world rasterised at 1 cm, the space reachable from
// the spawn point, and the raster cells of its bounding box (the scored area).
struct OccupancyTruth {
  sim::OccupancyRaster raster;
  ReachableSpace space;                  // points into `raster`: keep the object where it is
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // raster cells of the reachable space's bounding box
  // By raster cell: left out of the score, neither free nor not (empty: every cell is scored).
  std::vector<char> unscored;

  bool CellFree(int ix, int iy) const {
    return space.free[static_cast<std::size_t>(iy) * raster.width + ix] != 0;
  }
  // The centre of a reachable cell on the raster's edge, or nothing. The raster ends at the world
  // geometry's bounding box, so such a cell means no wall closes the space round the spawn: the
  // truth would end where nothing in the world does. Call after FitScoredBox.
  std::optional<Eigen::Vector2d> ReachableCellOnTheEdge() const;
  // Sets the scored box to the bounding box of `space` (empty: x1 < x0).
  void FitScoredBox();
};

// A scorer never reports a number against empty ground truth:
// @throws sim::ConfigError naming `spawn_source` (the experiment or the run's config.yaml) and
// robot.spawn when no free space is reachable from `start_W` (e would be 0 / 0), and naming it
// and world when the model has no upright static geometry to rasterise (a floor alone).
std::unique_ptr<OccupancyTruth> MakeOccupancyTruth(const mjModel* model,
                                                   const Eigen::Vector2d& start_W,
                                                   const std::string& spawn_source);

// A map's occupancy error e = A_e / A_tot: A_tot the reachable free area, A_e the area of the
// scored box (less its unscored cells) whose free / not-free label differs from the map's, sampled
// at the truth's cell centres. `map_says_free(p_W)` is the map's label of a world point.
struct OccupancyError {
  double total_cells = 0.0;
  double error_cells = 0.0;
  double cell_area_m2 = 0.0;
  double Error() const {  // NaN (JSON null) without free space; MakeOccupancyTruth refuses that
    return total_cells > 0 ? error_cells / total_cells : std::numeric_limits<double>::quiet_NaN();
  }
  double AreaTotalM2() const { return total_cells * cell_area_m2; }
  double AreaErrorM2() const { return error_cells * cell_area_m2; }
};
OccupancyError ScoreOccupancy(const OccupancyTruth& truth,
                              const std::function<bool(const Eigen::Vector2d&)>& map_says_free);

}  // namespace plywood::eval
