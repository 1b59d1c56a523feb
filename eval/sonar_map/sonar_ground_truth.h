#pragma once

#include <Eigen/Core>
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

}  // namespace plywood::eval
