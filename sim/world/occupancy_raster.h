#pragma once

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <vector>

#include "sim/world/ground_truth_walls.h"

namespace plywood::sim {

// The cell edges of the rasters a run is scored or drawn with: the sonar map's occupancy truth
// (eval::MakeOccupancyTruth, also `plywood score grid`) and the geometric map's picture.
inline constexpr double kOccupancyTruthResolutionM = 0.01;
inline constexpr double kGeometricMapPictureResolutionM = 0.02;

// The most cells a raster may hold: a 50 x 50 m world at the sonar map's 0.01 m, some 0.8 GB while
// it is scored (about 30 bytes a cell: the samples, the cells, the reachable space, the flood's
// stack; measured at 6e6 and 6e7 cells). Past it the memory grows with the world's extent squared:
// a box 20 km long took 19 GB and 197 s, a stray geom 3 km from the room more than any machine has
// (s61). A seed 001 room is 3.5 x 3 m, the office 14 x 5 m.
inline constexpr double kMaxOccupancyRasterCells = 2.5e7;

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

// The rectangle RasteriseOccupancy covers: options.bounds_W, else the bounding box of the geoms'
// cross-sections at every height (empty when there are none).
Eigen::AlignedBox2d OccupancyRasterBounds(const std::vector<UprightGeom>& geoms,
                                          const OccupancyRasterOptions& options);

// The number of cells of `resolution_m` that cover `bounds` (as a double: it may not fit an int).
double OccupancyRasterCells(const Eigen::AlignedBox2d& bounds, double resolution_m);

// Rasterises `geoms` (e.g. from ExtractUprightGeoms) that span options.height_m. A sample is
// occupied when it lies inside or on the boundary of any geom's cross-section; overlapping geoms
// count once.
// @throws std::invalid_argument if `options` is invalid, no bounds can be found (unset bounds
// and no geoms) or the raster would hold more than kMaxOccupancyRasterCells cells.
OccupancyRaster RasteriseOccupancy(const std::vector<UprightGeom>& geoms,
                                   const OccupancyRasterOptions& options);

// Rasterises the static upright boxes, cylinders, capsules and spheres of a compiled model (world
// alone or world + robot). Tilted static geoms, ellipsoids and meshes are not represented (see
// ExtractGroundTruthWalls).
// @throws std::invalid_argument as above.
OccupancyRaster RasteriseOccupancy(const mjModel* model, const OccupancyRasterOptions& options);

}  // namespace plywood::sim
