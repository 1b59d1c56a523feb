#include "sim/world/occupancy_raster.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"

namespace plywood::sim {
namespace {

// Cross-section bounding box of one geom in the world frame.
Eigen::AlignedBox2d BoundsOf(const UprightGeom& geom) {
  const Eigen::Vector2d half = geom.shape == UprightGeom::Shape::kCylinder
                                   ? Eigen::Vector2d(geom.radius_m, geom.radius_m)
                                   : Eigen::Vector2d(geom.R_WG.cwiseAbs() * geom.half_size_xy);
  return Eigen::AlignedBox2d(geom.centre_W - half, geom.centre_W + half);
}

// Cells needed to cover `extent_m`, tolerating round-off when the extent is a whole multiple.
double CellsToCover(double extent_m, double resolution_m) {
  return std::max(1.0, std::ceil(extent_m / resolution_m - 1e-9));
}

}  // namespace

void OccupancyRasterOptions::Validate() const {
  if (!(resolution_m > 0.0) || !std::isfinite(resolution_m)) {
    throw std::invalid_argument("resolution_m: must be a finite number > 0, got " +
                                msgs::ShortestNumber(resolution_m));
  }
  if (!std::isfinite(height_m)) {
    throw std::invalid_argument("height_m: must be finite, got " + msgs::ShortestNumber(height_m));
  }
  if (supersamples < 1 || supersamples > 8) {
    throw std::invalid_argument("supersamples: must be in [1, 8], got " +
                                std::to_string(supersamples));
  }
  if (bounds_W &&
      (bounds_W->isEmpty() || !bounds_W->min().allFinite() || !bounds_W->max().allFinite())) {
    throw std::invalid_argument("bounds_W: must be a finite, non-empty rectangle");
  }
  if (excluded_geom_group < -1 || excluded_geom_group >= mjNGROUP) {
    throw std::invalid_argument("excluded_geom_group: must be -1 (none) or a group in [0, " +
                                std::to_string(mjNGROUP - 1) + "], got " +
                                std::to_string(excluded_geom_group));
  }
}

Eigen::Vector2d OccupancyRaster::CellCentre(int ix, int iy) const {
  return origin_xy + resolution_m * Eigen::Vector2d(ix + 0.5, iy + 0.5);
}

std::optional<Eigen::Vector2i> OccupancyRaster::CellAt(const Eigen::Vector2d& p_W) const {
  const Eigen::Vector2d q = (p_W - origin_xy) / resolution_m;
  const int ix = static_cast<int>(std::floor(q.x()));
  const int iy = static_cast<int>(std::floor(q.y()));
  if (ix < 0 || iy < 0 || ix >= width || iy >= height) return std::nullopt;
  return Eigen::Vector2i(ix, iy);
}

double OccupancyRaster::OccupiedAreaM2() const {
  double sum = 0.0;
  for (const std::uint8_t c : cells) sum += c;
  return sum / 255.0 * resolution_m * resolution_m;
}

Eigen::AlignedBox2d OccupancyRasterBounds(const std::vector<UprightGeom>& geoms,
                                          const OccupancyRasterOptions& options) {
  if (options.bounds_W) return *options.bounds_W;
  Eigen::AlignedBox2d bounds;  // empty
  for (const UprightGeom& g : geoms) bounds.extend(BoundsOf(g));
  return bounds;
}

double OccupancyRasterCells(const Eigen::AlignedBox2d& bounds, double resolution_m) {
  return CellsToCover(bounds.sizes().x(), resolution_m) *
         CellsToCover(bounds.sizes().y(), resolution_m);
}

OccupancyRaster RasteriseOccupancy(const std::vector<UprightGeom>& geoms,
                                   const OccupancyRasterOptions& options) {
  options.Validate();
  const Eigen::AlignedBox2d bounds = OccupancyRasterBounds(geoms, options);
  if (bounds.isEmpty()) {
    throw std::invalid_argument("bounds_W: unset and there is no geometry to take it from");
  }
  // Checked before the cells are counted in ints: a raster past the limit would not fit memory.
  const double cells = OccupancyRasterCells(bounds, options.resolution_m);
  if (!(cells <= kMaxOccupancyRasterCells)) {
    throw std::invalid_argument("bounds_W: " + msgs::ShortestNumber(bounds.sizes().x()) + " x " +
                                msgs::ShortestNumber(bounds.sizes().y()) + " m in cells of " +
                                msgs::ShortestNumber(options.resolution_m) + " m would be " +
                                msgs::ShortestNumber(cells) + " cells, more than the limit of " +
                                msgs::ShortestNumber(kMaxOccupancyRasterCells));
  }
  OccupancyRaster raster;
  raster.origin_xy = bounds.min();
  raster.resolution_m = options.resolution_m;
  raster.width = static_cast<int>(CellsToCover(bounds.sizes().x(), options.resolution_m));
  raster.height = static_cast<int>(CellsToCover(bounds.sizes().y(), options.resolution_m));
  const size_t n_cells = static_cast<size_t>(raster.width) * raster.height;

  // One bit per sample, so a sample covered by two touching or overlapping geoms counts once.
  const int k = options.supersamples;
  std::vector<std::uint64_t> sample_bits(n_cells, 0);
  const double step = options.resolution_m / k;
  for (const UprightGeom& g : geoms) {
    if (options.height_m < g.z_min_m || options.height_m > g.z_max_m) continue;
    const Eigen::AlignedBox2d box = BoundsOf(g);
    const Eigen::Vector2d lo = (box.min() - raster.origin_xy) / options.resolution_m;
    const Eigen::Vector2d hi = (box.max() - raster.origin_xy) / options.resolution_m;
    const int ix0 = std::max(0, static_cast<int>(std::floor(lo.x())));
    const int iy0 = std::max(0, static_cast<int>(std::floor(lo.y())));
    const int ix1 = std::min(raster.width - 1, static_cast<int>(std::floor(hi.x())));
    const int iy1 = std::min(raster.height - 1, static_cast<int>(std::floor(hi.y())));
    for (int iy = iy0; iy <= iy1; ++iy) {
      for (int ix = ix0; ix <= ix1; ++ix) {
        std::uint64_t& bits = sample_bits[static_cast<size_t>(iy) * raster.width + ix];
        const Eigen::Vector2d corner =
            raster.origin_xy + options.resolution_m * Eigen::Vector2d(ix, iy);
        for (int sy = 0; sy < k; ++sy) {
          for (int sx = 0; sx < k; ++sx) {
            const Eigen::Vector2d p = corner + step * Eigen::Vector2d(sx + 0.5, sy + 0.5);
            if (g.ContainsXY(p)) bits |= std::uint64_t{1} << (sy * k + sx);
          }
        }
      }
    }
  }
  raster.cells.resize(n_cells);
  const double samples = static_cast<double>(k * k);
  for (size_t i = 0; i < n_cells; ++i) {
    raster.cells[i] = static_cast<std::uint8_t>(
        std::lround(OccupancyRaster::kOccupied * std::popcount(sample_bits[i]) / samples));
  }
  return raster;
}

OccupancyRaster RasteriseOccupancy(const mjModel* model, const OccupancyRasterOptions& options) {
  options.Validate();
  GroundTruthOptions geom_options;
  geom_options.excluded_geom_group = options.excluded_geom_group;
  // Every height: the default bounds must not depend on the slice.
  return RasteriseOccupancy(ExtractUprightGeoms(model, geom_options), options);
}

}  // namespace plywood::sim
