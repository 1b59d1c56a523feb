#pragma once

#include <mujoco/mujoco.h>

#include <cstdint>
#include <vector>

#include "sim/raycast/ray_caster.h"

namespace plywood::sim {

struct GridRayCaster2DOptions {
  // Edge of the square grid cells. Smaller cells mean fewer candidate geoms per cell but more
  // cell steps per ray; 0.5 m suits rooms whose walls are a few metres long (see
  // RunRayCasterBench).
  double cell_size_m = 0.5;
  // The grid never exceeds this many cells: cells grow until it fits (huge worlds).
  int max_cells = 1 << 22;
  // A ray this close to horizontal (rad) is cast level, along its heading: a robot's pitch and roll
  // jitter (up to ~8e-4 rad on plywood) otherwise sends most rays through mju_rayGeom (1e-3 cuts
  // the office bench's casting by 36 %). The range then differs by at most 1 - cos(tolerance)
  // relative (5e-7 at 1e-3: 4 um at 8 m, far below any simulated sensor's noise or resolution),
  // and the height at which a ray meets an object by at most tolerance x range (8 mm at 8 m).
  // 1e-3 (the default) covers the measured jitter with a margin. In [0, 0.01]; 0 casts every ray
  // exactly as given (bit-identical to mj_ray).
  double level_tolerance_rad = 1e-3;

  // @throws std::invalid_argument naming the field.
  void Validate() const;
};

// A ray caster that returns exactly what MujocoRayCaster returns (same distance to the last bit on
// the fast path, same geom id, same normal rule) but tests only the geoms near the ray; a ray
// within level_tolerance_rad of horizontal is first levelled (see the option).
//
// At construction every static geom (welded to the world: body_weldid == 0) that rays can see and
// that has a finite footprint (box, cylinder, sphere, capsule, ellipsoid) is rasterised into a
// uniform 2-D grid over its footprint on the floor plane, with its z range. A ray walks the grid
// cells under its floor-plane projection with the 3-D DDA of Amanatides & Woo ("A fast voxel
// traversal algorithm for ray tracing", Eurographics 1987) restricted to x and y, tests the geoms
// of each cell whose z range meets the ray's z range within that cell, and stops at the first cell
// that ends beyond the nearest hit. Upright boxes and cylinders (local z exactly vertical) hit by a
// horizontal ray use a 2-D test that reproduces mj_ray's arithmetic; any other pairing calls
// MuJoCo's own per-geom intersection (mju_rayGeom).
//
// Geoms outside the grid are tested on every ray with MuJoCo's per-geom functions, reading their
// pose from `data` at cast time: geoms on moving bodies (never the robot's: its geom group is not
// seen), planes, meshes and height fields. A plane whose normal is exactly vertical (the floor)
// cannot be hit by a horizontal ray and is skipped for those. With a static world and a horizontal
// ray no per-geom MuJoCo call is made at all.
//
// Cast allocates nothing and mutates nothing, so one caster serves several threads.
class GridRayCaster2D : public RayCaster {
 public:
  // @pre mj_forward (or mj_kinematics) has run on `data`, so static geom poses are final.
  // `model` and `data` must outlive the caster.
  // @throws std::invalid_argument if `options` is invalid or data holds no geom poses yet.
  GridRayCaster2D(const mjModel* model, const mjData* data,
                  const GridRayCaster2DOptions& options = {});

  GridRayCaster2D(const GridRayCaster2D&) = delete;
  GridRayCaster2D& operator=(const GridRayCaster2D&) = delete;

  bool Cast(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W, double max_range_m,
            RayHit* hit) const override;
  bool CastWithoutNormal(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W,
                         double max_range_m, RayHit* hit) const override;
  // Same results as Cast / CastWithoutNormal ray by ray. The rays that are (or are levelled to)
  // horizontal share one set-up: with c the centre of the origins' bounding box and r the largest
  // distance of an origin from it (0 for a scan's beams), the grid shapes whose z range meets the
  // origins' heights are collected, each with the angular interval its padded floor-plane
  // footprint spans from c (widened by tan(asin(r / d)) for a footprint d from c, or the whole
  // circle when d < r + 1 mm) and a lower bound of its distance from any origin, sorted by that
  // bound into angular bins; a ray then tests only its bin's shapes whose interval holds its
  // direction, nearest first, and stops at the first shape farther than its nearest hit. The shapes
  // are collected reach by reach: first those in the cells within 3 m (plus r) of c, then, for the
  // rays whose hit is not nearer than that, those under the next stretch (to twice the reach,
  // up to max_range_m) of those rays' angular bins, and so on; a ray is final once its hit lies
  // within the stretch covered. So shapes behind the walls that end most rays are never collected,
  // and the cost does not grow with the world beyond them. Every shape a ray can hit before its
  // nearest hit is tested with the same arithmetic as Cast, so distances, geoms and normals are
  // the same bits. Other rays go through Cast. Uses a per-thread scratch buffer (allocates only
  // while it grows), so one caster still serves several threads.
  void CastBatch(const Eigen::Vector3d* origins_W, const Eigen::Vector3d* dirs_W, int count,
                 double max_range_m, bool with_normal, RayHit* hits, bool* found) const override;
  // CastBatch with one origin for every ray, without normals (a scan's beams).
  void CastFanWithoutNormal(const Eigen::Vector3d& origin_W, const Eigen::Vector3d* dirs_W,
                            int count, double max_range_m, RayHit* hits,
                            bool* found) const override;

  // Geoms held in the grid, and geoms tested on every (non-horizontal) ray.
  int num_grid_geoms() const { return static_cast<int>(shapes_.size()); }
  int num_fallback_geoms() const { return static_cast<int>(fallback_all_.size()); }
  int num_horizontal_fallback_geoms() const {
    return static_cast<int>(fallback_horizontal_.size());
  }
  int num_cells_x() const { return nx_; }
  int num_cells_y() const { return ny_; }
  double cell_size_m() const { return cell_m_; }

 private:
  struct Shape {
    double z_min, z_max;  // world z range, padded
    double pos[3];        // geom_xpos
    double mat[9];        // geom_xmat (row-major, geom axes as columns)
    double size[3];       // geom_size
    double half_height;   // size[2] for boxes, size[1] for cylinders: the upright test's z extent
    int geom_id;
    int type;      // mjtGeom
    bool upright;  // local z exactly along world z (mat[2] == mat[5] == 0): 2-D fast path
  };

  // A shape's padded footprint on the floor plane: a rectangle (the box's own for upright boxes,
  // the bounding box of the footprint otherwise) for the fan's angular intervals and distances.
  struct Footprint {
    double centre[2];
    double axis_x[2], axis_y[2];  // unit axes in the floor plane
    double half[2];               // padded half extents along them
    double corner[4][2];
  };

  bool CastRay(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W, double max_range_m,
               bool with_normal, RayHit* hit) const;
  // dir_W with its z set to 0 and renormalised when it is within level_tolerance_rad of level
  // (CastRay and CastRays level alike), else dir_W.
  Eigen::Vector3d LevelledDirection(const Eigen::Vector3d& dir_W) const;
  // CastBatch's work; ray i starts at origins_W[i * origin_step] (origin_step 0 or 1).
  void CastRays(const Eigen::Vector3d* origins_W, int origin_step, const Eigen::Vector3d* dirs_W,
                int count, double max_range_m, bool with_normal, RayHit* hits, bool* found) const;
  // The hit's normal, as Cast gives it (dir_W: the levelled direction).
  void SetNormal(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W, RayHit* hit) const;
  double IntersectShape(const Shape& shape, const double* origin, const double* dir,
                        bool horizontal) const;
  double IntersectFallback(int geom_id, const double* origin, const double* dir) const;

  const mjModel* model_;
  const mjData* data_;
  double level_tolerance_ = 0.0;  // as tan: |dir z| <= this x |dir xy| counts as level
  std::vector<Shape> shapes_;
  std::vector<Footprint> footprints_;     // by shape index
  std::vector<int> fallback_all_;         // tested on non-horizontal rays
  std::vector<int> fallback_horizontal_;  // tested on horizontal rays
  double x0_ = 0.0, y0_ = 0.0;            // grid corner
  double cell_m_ = 0.5, inv_cell_ = 2.0;
  int nx_ = 0, ny_ = 0;
  std::vector<uint32_t> cell_begin_;  // CSR: shapes of cell c are cell_items_[begin[c]..begin[c+1])
  std::vector<uint32_t> cell_items_;
};

}  // namespace plywood::sim
