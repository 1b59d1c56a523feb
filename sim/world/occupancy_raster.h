#pragma once

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <vector>

#include "sim/world/ground_truth_walls.h"

namespace plywood::sim {

struct OccupancyRasterOptions {
  double resolution_m = 0.05;  // cell edge
  double height_m = 0.2;       // the horizontal slice that is rasterised
  // k: each cell is sampled on a k x k sub-grid and stores the occupied fraction (exact area in the
  // limit); 1 samples the cell centre only, so cells are all-or-nothing. At most 8.
  int supersamples = 1;
  // The rasterised rectangle in the world frame; unset: the bounding box of the world's static
  // upright geoms at every height (planes and the robot excluded), so it does not vary with
  // height_m. Cells are laid from bounds_W->min() and cover at least the whole rectangle.
  std::optional<Eigen::AlignedBox2d> bounds_W;
  int excluded_geom_group = 3;  // the robot's geoms (sim::Scene::kRobotGeomGroup)

  // @throws std::invalid_argument naming the field.
  void Validate() const;
};

// A ground-truth occupancy grid of the world's static geometry in one horizontal slice.
// Cell (ix, iy) covers [origin_xy + (ix, iy) * resolution_m, origin_xy + (ix + 1, iy + 1) *
// resolution_m) in the world frame; rows run along +x and are stored from the lowest y up.
struct OccupancyRaster {
  static constexpr std::uint8_t kFree = 0;
  static constexpr std::uint8_t kOccupied = 255;

  Eigen::Vector2d origin_xy = Eigen::Vector2d::Zero();  // world x, y of cell (0, 0)'s low corner
  double resolution_m = 0.0;
  int width = 0;   // cells along x
  int height = 0;  // cells along y
  // cells[iy * width + ix] = round(255 * occupied fraction of the cell's samples).
  std::vector<std::uint8_t> cells;

  std::uint8_t at(int ix, int iy) const { return cells[static_cast<size_t>(iy) * width + ix]; }
  double OccupiedFraction(int ix, int iy) const { return at(ix, iy) / 255.0; }
  // At least half the cell's samples are occupied (with one sample: the centre is inside).
  bool IsOccupied(int ix, int iy) const { return at(ix, iy) >= 128; }
  Eigen::Vector2d CellCentre(int ix, int iy) const;
  // The cell holding world point p_W, or nothing when it is outside the raster.
  std::optional<Eigen::Vector2i> CellAt(const Eigen::Vector2d& p_W) const;
  // Sum over cells of occupied fraction times cell area (m^2).
  double OccupiedAreaM2() const;
};

// Rasterises `geoms` (e.g. from ExtractUprightGeoms) that span options.height_m. A sample is
// occupied when it lies inside or on the boundary of any geom's cross-section; overlapping geoms
// count once.
// @throws std::invalid_argument if `options` is invalid or no bounds can be found (unset bounds
// and no geoms).
OccupancyRaster RasteriseOccupancy(const std::vector<UprightGeom>& geoms,
                                   const OccupancyRasterOptions& options);

// Rasterises the static upright boxes, cylinders, capsules and spheres of a compiled model (world
// alone or world + robot). Tilted static geoms, ellipsoids and meshes are not represented (see
// ExtractGroundTruthWalls).
// @throws std::invalid_argument as above.
OccupancyRaster RasteriseOccupancy(const mjModel* model, const OccupancyRasterOptions& options);

}  // namespace plywood::sim
