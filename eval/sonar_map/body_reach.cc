#include "eval/sonar_map/body_reach.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "eval/sonar_map/squared_distance_transform.h"

namespace plywood::eval {

ReachableSpace ComputeBodyReachableSpace(const sim::OccupancyRaster& raster,
                                         const Eigen::Vector2d& start_W, double body_radius_m) {
  ReachableSpace space;
  space.raster = &raster;
  const int width = raster.width, height = raster.height;
  const std::size_t n = static_cast<std::size_t>(width) * height;
  space.free.assign(n, 0);
  const auto start = raster.CellAt(start_W);
  if (!start || raster.IsOccupied(start->x(), start->y())) return space;
  const auto index = [width](int ix, int iy) { return static_cast<std::size_t>(iy) * width + ix; };

  std::vector<char> occupied(n, 0);
  for (int iy = 0; iy < height; ++iy)
    for (int ix = 0; ix < width; ++ix) occupied[index(ix, iy)] = raster.IsOccupied(ix, iy);
  const std::vector<double> to_occupied = SquaredDistanceToSet(occupied, width, height);
  // Clearance in cells: from a cell's centre to the nearest occupied one's (kNoSetCell: no wall).
  const auto clearance = [&](std::size_t i) { return std::sqrt(to_occupied[i]); };
  const double radius_cells =
      std::min(body_radius_m / raster.resolution_m, clearance(index(start->x(), start->y())));

  // Where a body's centre fits (anywhere), and those of them it reaches from the start: a
  // 4-connected flood over the fitting cells.
  std::vector<char> fits(n, 0), centres(n, 0);
  for (std::size_t i = 0; i < n; ++i) fits[i] = !occupied[i] && clearance(i) >= radius_cells;
  const std::size_t start_index = index(start->x(), start->y());
  fits[start_index] = 1;
  const Eigen::Vector2i steps[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  const auto flood = [&](const std::vector<char>& passable, std::vector<char>& reached) {
    std::vector<Eigen::Vector2i> stack{*start};
    reached[start_index] = 1;
    while (!stack.empty()) {
      const Eigen::Vector2i c = stack.back();
      stack.pop_back();
      for (const auto& s : steps) {
        const Eigen::Vector2i m = c + s;
        if (m.x() < 0 || m.y() < 0 || m.x() >= width || m.y() >= height) continue;
        const std::size_t i = index(m.x(), m.y());
        if (reached[i] || !passable[i]) continue;
        reached[i] = 1;
        stack.push_back(m);
      }
    }
  };
  flood(fits, centres);
  // What bodies sweep: from the centres the robot reaches, and from those elsewhere (rooms behind
  // a gap narrower than the body). The latter, less what the robot sweeps itself, is what the
  // robot cannot map by going there.
  const double covered2 = radius_cells * radius_cells;
  const std::vector<double> to_centre = SquaredDistanceToSet(centres, width, height);
  const std::vector<double> to_fit = SquaredDistanceToSet(fits, width, height);
  std::vector<char> passable(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    passable[i] = !occupied[i] && !(to_fit[i] <= covered2 && to_centre[i] > covered2);
  // The rest, as a point reaches it from the start: the robot's swept space, the corners and nooks
  // it cannot fill, and the narrow gaps themselves.
  flood(passable, space.free);
  return space;
}

std::unique_ptr<OccupancyTruth> MakeBodyReachTruth(const OccupancyTruth& truth,
                                                   const Eigen::Vector2d& start_W,
                                                   double body_radius_m) {
  auto body = std::make_unique<OccupancyTruth>();
  body->raster = truth.raster;
  body->space = ComputeBodyReachableSpace(body->raster, start_W, body_radius_m);
  body->unscored.assign(truth.space.free.size(), 0);
  for (std::size_t i = 0; i < body->space.free.size(); ++i)
    body->unscored[i] = truth.space.free[i] && !body->space.free[i];
  body->FitScoredBox();
  return body;
}

}  // namespace plywood::eval
