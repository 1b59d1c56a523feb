#include "sim/raycast/grid_ray_caster_2d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"
#include "sim/raycast/mujoco_ray_caster.h"
#include "sim/raycast/surface_normal.h"

namespace plywood::sim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Footprints and z ranges are padded so a hit on (or within rounding of) a cell boundary is found
// from both cells; the traversal may then stop as soon as a cell ends beyond the nearest hit.
constexpr double kPadM = 1e-6;
constexpr double kStopSlackM = 1e-9;

struct Aabb {
  double lo[3];
  double hi[3];
};

// World-frame half extents of a geom about its centre.
bool HalfExtents(int type, const mjtNum* R, const mjtNum* size, double half[3]) {
  for (int k = 0; k < 3; ++k) {
    const mjtNum* row = R + 3 * k;  // world axis k expressed in geom axes
    switch (type) {
      case mjGEOM_BOX:
        half[k] =
            std::abs(row[0]) * size[0] + std::abs(row[1]) * size[1] + std::abs(row[2]) * size[2];
        break;
      case mjGEOM_CYLINDER:
        half[k] =
            std::abs(row[2]) * size[1] + size[0] * std::sqrt(std::max(0.0, 1.0 - row[2] * row[2]));
        break;
      case mjGEOM_CAPSULE:
        half[k] = std::abs(row[2]) * size[1] + size[0];
        break;
      case mjGEOM_SPHERE:
        half[k] = size[0];
        break;
      case mjGEOM_ELLIPSOID:
        half[k] = std::hypot(row[0] * size[0], row[1] * size[1], row[2] * size[2]);
        break;
      default:
        return false;
    }
  }
  return true;
}

// mj_ray's quadratic: smallest non-negative root of a x^2 + 2 b x + c = 0, or -1. Kept in the same
// arithmetic as MuJoCo (including its mjMINVAL cut on the discriminant) so distances agree bitwise.
inline double SmallestRoot(double a, double b, double c) {
  double det = b * b - a * c;
  if (det < mjMINVAL) return -1;
  det = std::sqrt(det);
  const double x0 = (-b - det) / a;
  if (x0 >= 0) return x0;
  const double x1 = (-b + det) / a;
  return x1 >= 0 ? x1 : -1;
}

// mj_ray's test of an upright box's two faces across one local axis (half extent `half_across`)
// for a horizontal ray at p moving by v per unit t: the smallest t >= 0 at which the ray meets one
// of them within `half_along` of the box's centre line, or -1. The face the ray moves towards is
// tried first: the far face's t is never smaller (the numerator and the division by the same v
// round monotonically), so it is computed only when the near face is missed. Same bits as trying
// both and keeping the smaller.
inline double FacePairHit(double half_across, double half_along, double p_across, double p_along,
                          double v_across, double v_along) {
  const double near_face = v_across > 0 ? -half_across : half_across;
  double t = (near_face - p_across) / v_across;
  if (t >= 0 && std::abs(p_along + t * v_along) <= half_along) return t;
  t = (-near_face - p_across) / v_across;
  if (t >= 0 && std::abs(p_along + t * v_along) <= half_along) return t;
  return -1;
}

// The nearest hit of one ray so far; exact ties go to the lower geom id, as in mj_ray's loop over
// geoms.
struct NearestHit {
  double t = kInf;
  int id = std::numeric_limits<int>::max();
  void Consider(double candidate_t, int candidate_id) {
    if (candidate_t >= 0 && (candidate_t < t || (candidate_t == t && candidate_id < id))) {
      t = candidate_t;
      id = candidate_id;
    }
  }
  // A hit within max_range_m: written to *hit (distance and geom).
  bool Report(double max_range_m, RayHit* hit) const {
    if (id == std::numeric_limits<int>::max() || t > max_range_m) return false;
    hit->distance_m = t;
    hit->geom_id = id;
    return true;
  }
};

// A monotonic stand-in for the angle of (x, y) in [0, 2 pi): 0 along +x, 1 along +y, 2 along -x,
// 3 along -y, in [0, 4). (x, y) must not be (0, 0).
inline double DiamondAngle(double x, double y) {
  if (y >= 0) return x >= 0 ? y / (x + y) : 1.0 - x / (y - x);
  return x < 0 ? 2.0 - y / (-x - y) : 3.0 + x / (x - y);
}

// The fan's angular bins over [0, 4) and what a bin holds: a piece of a shape's angular interval.
constexpr int kFanBins = 32;
inline int FanBin(double key) {
  return std::clamp(static_cast<int>(key * (kFanBins / 4.0)), 0, kFanBins - 1);
}
struct FanCandidate {
  double min_d;   // a lower bound of the distance from the origin to the shape's footprint
  double lo, hi;  // its angular interval (DiamondAngle), lo may be < 0 or hi >= 4: it wraps
  uint32_t shape;
};
struct FanEntry {
  double lo, hi;  // within [0, 4]
  double min_d;
  uint32_t shape;
};
// A horizontal ray whose hit is not final yet: its levelled direction, DiamondAngle, nearest hit
// so far and index.
struct PendingRay {
  Eigen::Vector3d dir;
  double key;
  NearestHit nearest;
  uint32_t index;
};
// The cells under the bounding box of the pending rays' stretches in one angular bin.
struct FanBox {
  int ix0, ix1, iy0, iy1;
};
// The unit directions of the bins' edges: dir[b] is the direction of DiamondAngle b * 4 / kFanBins
// (dir[kFanBins] == dir[0]).
struct FanBinDirections {
  double dir[kFanBins + 1][2];
};
const FanBinDirections& TheFanBinDirections() {
  static const FanBinDirections table = [] {
    FanBinDirections t;
    for (int b = 0; b <= kFanBins; ++b) {
      const double key = 4.0 * b / kFanBins;
      const int quadrant = static_cast<int>(key) % 4;
      const double f = key - std::floor(key);  // DiamondAngle f within the quadrant: (1 - f, f)
      const double n = std::hypot(1.0 - f, f);
      double x = (1.0 - f) / n, y = f / n;
      for (int q = 0; q < quadrant; ++q) {  // turn by +90 deg
        const double turned = -y;
        y = x;
        x = turned;
      }
      t.dir[b][0] = x;
      t.dir[b][1] = y;
    }
    return t;
  }();
  return table;
}
struct FanScratch {
  std::vector<uint32_t> stamp;  // by shape index: the epoch in which it was last collected
  uint32_t epoch = 0;
  std::vector<PendingRay> pending;  // horizontal rays not final after the first reach
  FanBox boxes[kFanBins];
  std::vector<FanCandidate> candidates;
  std::vector<uint32_t> bin_begin;  // CSR over kFanBins bins
  std::vector<uint32_t> bin_fill;
  std::vector<FanEntry> entries;
};
FanScratch& ThreadFanScratch() {
  thread_local FanScratch scratch;
  return scratch;
}

// Distances below this from a footprint take the whole circle: its angular span from so near a
// point could come within rounding of pi.
constexpr double kFanNearM = 1e-3;
// Widening of the angular intervals (DiamondAngle units; their rounding is ~1e-15) and the
// shortening of the distance bounds (m); the footprints are padded by kPadM besides.
constexpr double kFanAngleSlack = 1e-9;
constexpr double kFanDistanceSlackM = 1e-7;
// The reaches (ray parameter) out to which CastRays collects shapes: the first, then each this
// many times the last, until max_range_m. A hit short of the reach covered so far by more than
// kFanFinalSlackM (a few times the cells' padding kPadM) is final.
constexpr double kFanFirstReachM = 3.0;
constexpr double kFanReachGrowth = 2.0;
constexpr double kFanFinalSlackM = 1e-5;

}  // namespace

void GridRayCaster2DOptions::Validate() const {
  if (!(cell_size_m > 0.0) || !std::isfinite(cell_size_m)) {
    throw std::invalid_argument("cell_size_m: must be > 0, got " +
                                msgs::ShortestNumber(cell_size_m));
  }
  if (max_cells < 1) {
    throw std::invalid_argument("max_cells: must be >= 1, got " + std::to_string(max_cells));
  }
  if (!(level_tolerance_rad >= 0.0 && level_tolerance_rad <= 0.01)) {
    throw std::invalid_argument("level_tolerance_rad: must be in [0, 0.01], got " +
                                msgs::ShortestNumber(level_tolerance_rad));
  }
}

GridRayCaster2D::GridRayCaster2D(const mjModel* model, const mjData* data,
                                 const GridRayCaster2DOptions& options)
    : model_(model), data_(data) {
  options.Validate();
  level_tolerance_ = std::tan(options.level_tolerance_rad);

  std::vector<Aabb> boxes;
  for (int g = 0; g < model->ngeom; ++g) {
    if (!IsRayVisibleGeom(model, g)) continue;
    const int type = model->geom_type[g];
    const mjtNum* R = data->geom_xmat + 9 * g;
    const bool is_static = model->body_weldid[model->geom_bodyid[g]] == 0;
    double half[3];
    // A geom beyond any room's size (an absurd MJCF) is tested by MuJoCo for every ray instead:
    // its grid cells would not fit an int.
    constexpr double kGriddedLimitM = 1e6;
    const mjtNum* p = data->geom_xpos + 3 * g;
    if (!is_static || !HalfExtents(type, R, model->geom_size + 3 * g, half) ||
        !(std::max({std::abs(p[0]), std::abs(p[1]), half[0], half[1]}) < kGriddedLimitM)) {
      fallback_all_.push_back(g);
      // Only a static plane facing exactly up or down is provably never hit by a horizontal ray.
      const bool flat_plane = is_static && type == mjGEOM_PLANE && R[2] == 0 && R[5] == 0;
      if (!flat_plane) fallback_horizontal_.push_back(g);
      continue;
    }
    if (R[0] == 0 && R[4] == 0 && R[8] == 0 && R[1] == 0 && R[3] == 0) {
      throw std::invalid_argument("data: geom poses are not computed; call mj_forward first");
    }
    Shape s;
    s.geom_id = g;
    s.type = type;
    for (int i = 0; i < 3; ++i) {
      s.pos[i] = data->geom_xpos[3 * g + i];
      s.size[i] = model->geom_size[3 * g + i];
    }
    std::copy(R, R + 9, s.mat);
    s.upright = (type == mjGEOM_BOX || type == mjGEOM_CYLINDER) && R[2] == 0 && R[5] == 0;
    s.half_height = type == mjGEOM_BOX ? s.size[2] : s.size[1];
    s.z_min = s.pos[2] - half[2] - kPadM;
    s.z_max = s.pos[2] + half[2] + kPadM;
    Aabb box;
    for (int k = 0; k < 3; ++k) {
      box.lo[k] = s.pos[k] - half[k] - kPadM;
      box.hi[k] = s.pos[k] + half[k] + kPadM;
    }
    Footprint f;
    f.centre[0] = s.pos[0];
    f.centre[1] = s.pos[1];
    if (s.upright && type == mjGEOM_BOX) {
      f.axis_x[0] = R[0];
      f.axis_x[1] = R[3];
      f.axis_y[0] = R[1];
      f.axis_y[1] = R[4];
      f.half[0] = s.size[0] + kPadM;
      f.half[1] = s.size[1] + kPadM;
    } else {
      f.axis_x[0] = 1.0;
      f.axis_x[1] = 0.0;
      f.axis_y[0] = 0.0;
      f.axis_y[1] = 1.0;
      f.half[0] = half[0] + kPadM;
      f.half[1] = half[1] + kPadM;
    }
    for (int c = 0; c < 4; ++c) {
      const double sx = (c & 1) ? 1.0 : -1.0, sy = (c & 2) ? 1.0 : -1.0;
      for (int k = 0; k < 2; ++k) {
        f.corner[c][k] = f.centre[k] + sx * f.half[0] * f.axis_x[k] + sy * f.half[1] * f.axis_y[k];
      }
    }
    shapes_.push_back(s);
    footprints_.push_back(f);
    boxes.push_back(box);
  }

  cell_m_ = options.cell_size_m;
  if (shapes_.empty()) {
    nx_ = ny_ = 0;
    cell_begin_.assign(1, 0);
    return;
  }
  double x1 = -kInf, y1 = -kInf;
  x0_ = y0_ = kInf;
  for (const Aabb& b : boxes) {
    x0_ = std::min(x0_, b.lo[0]);
    y0_ = std::min(y0_, b.lo[1]);
    x1 = std::max(x1, b.hi[0]);
    y1 = std::max(y1, b.hi[1]);
  }
  auto cells_along = [this](double extent) {
    return std::max(1, static_cast<int>(std::ceil(extent / cell_m_)));
  };
  while (static_cast<double>(cells_along(x1 - x0_)) * cells_along(y1 - y0_) > options.max_cells) {
    cell_m_ *= 2.0;
  }
  inv_cell_ = 1.0 / cell_m_;
  nx_ = cells_along(x1 - x0_);
  ny_ = cells_along(y1 - y0_);

  // Does shape s overlap cell (ix, iy)? Exact separating-axis test for upright boxes and circle
  // test for upright cylinders; the footprint's bounding box for everything else.
  auto overlaps = [this](const Shape& s, int ix, int iy) {
    if (!s.upright) return true;
    const double h = 0.5 * cell_m_ + kPadM;
    const double cx = x0_ + (ix + 0.5) * cell_m_ - s.pos[0];
    const double cy = y0_ + (iy + 0.5) * cell_m_ - s.pos[1];
    if (s.type == mjGEOM_CYLINDER) {
      const double dx = std::max(0.0, std::abs(cx) - h);
      const double dy = std::max(0.0, std::abs(cy) - h);
      return std::hypot(dx, dy) <= s.size[0] + kPadM;
    }
    for (int axis = 0; axis < 2; ++axis) {  // the box's own x and y axes in the floor plane
      const double ux = s.mat[axis], uy = s.mat[3 + axis];
      const double cell_radius = (std::abs(ux) + std::abs(uy)) * h;
      if (std::abs(cx * ux + cy * uy) > cell_radius + s.size[axis] + kPadM) return false;
    }
    return true;
  };
  auto cell_range = [this](const Aabb& b, int* ix0, int* ix1, int* iy0, int* iy1) {
    *ix0 = std::clamp(static_cast<int>(std::floor((b.lo[0] - x0_) * inv_cell_)), 0, nx_ - 1);
    *ix1 = std::clamp(static_cast<int>(std::floor((b.hi[0] - x0_) * inv_cell_)), 0, nx_ - 1);
    *iy0 = std::clamp(static_cast<int>(std::floor((b.lo[1] - y0_) * inv_cell_)), 0, ny_ - 1);
    *iy1 = std::clamp(static_cast<int>(std::floor((b.hi[1] - y0_) * inv_cell_)), 0, ny_ - 1);
  };

  // Two passes (count, then fill) build the compressed per-cell lists.
  cell_begin_.assign(static_cast<size_t>(nx_) * ny_ + 1, 0);
  for (size_t i = 0; i < shapes_.size(); ++i) {
    int ix0, ix1, iy0, iy1;
    cell_range(boxes[i], &ix0, &ix1, &iy0, &iy1);
    for (int iy = iy0; iy <= iy1; ++iy) {
      for (int ix = ix0; ix <= ix1; ++ix) {
        if (overlaps(shapes_[i], ix, iy)) ++cell_begin_[iy * nx_ + ix + 1];
      }
    }
  }
  for (size_t c = 1; c < cell_begin_.size(); ++c) cell_begin_[c] += cell_begin_[c - 1];
  cell_items_.resize(cell_begin_.back());
  std::vector<uint32_t> fill(cell_begin_.begin(), cell_begin_.end() - 1);
  for (size_t i = 0; i < shapes_.size(); ++i) {
    int ix0, ix1, iy0, iy1;
    cell_range(boxes[i], &ix0, &ix1, &iy0, &iy1);
    for (int iy = iy0; iy <= iy1; ++iy) {
      for (int ix = ix0; ix <= ix1; ++ix) {
        if (overlaps(shapes_[i], ix, iy)) cell_items_[fill[iy * nx_ + ix]++] = i;
      }
    }
  }
}

// Inline: every ray passes here. The same bits as Eigen's head<2>().norm() and normalize() of
// (x, y, 0) (x * x + y * y, its square root, the quotients), with one square root instead of two.
inline Eigen::Vector3d GridRayCaster2D::LevelledDirection(const Eigen::Vector3d& dir_W) const {
  const double x = dir_W.x(), y = dir_W.y(), z = dir_W.z();
  if (z == 0.0) return dir_W;
  const double squared = x * x + y * y;
  const double norm = std::sqrt(squared);
  if (std::abs(z) > level_tolerance_ * norm) return dir_W;
  if (!(squared > 0.0)) return {x, y, 0.0};
  return {x / norm, y / norm, 0.0};
}

double GridRayCaster2D::IntersectShape(const Shape& s, const double* o, const double* v,
                                       bool horizontal) const {
  if (!(s.upright && horizontal)) {
    return mju_rayGeom(s.pos, s.mat, s.size, o, v, s.type);
  }
  // Horizontal ray, geom z exactly vertical: the geom-frame ray has lvec[2] == 0, so mj_ray's test
  // reduces to the floor-plane cross-section plus a height check, computed here in the same
  // floating-point order (ray_map, then the face or quadratic solution) so results match bitwise.
  const double* R = s.mat;
  const double d0 = o[0] - s.pos[0], d1 = o[1] - s.pos[1], d2 = o[2] - s.pos[2];
  const double lp2 = R[8] * d2;
  if (!(std::abs(lp2) <= s.half_height)) return -1;
  const double lp0 = R[0] * d0 + R[3] * d1 + R[6] * d2;
  const double lp1 = R[1] * d0 + R[4] * d1 + R[7] * d2;
  const double lv0 = R[0] * v[0] + R[3] * v[1];
  const double lv1 = R[1] * v[0] + R[4] * v[1];

  if (s.type == mjGEOM_CYLINDER) {
    const double a = lv0 * lv0 + lv1 * lv1;
    const double b = lv0 * lp0 + lv1 * lp1;
    const double c = lp0 * lp0 + lp1 * lp1 - s.size[0] * s.size[0];
    return SmallestRoot(a, b, c);
  }

  double x = -1;
  if (std::abs(lv0) > mjMINVAL) x = FacePairHit(s.size[0], s.size[1], lp0, lp1, lv0, lv1);
  if (std::abs(lv1) > mjMINVAL) {
    const double y = FacePairHit(s.size[1], s.size[0], lp1, lp0, lv1, lv0);
    if (y >= 0 && (x < 0 || y < x)) x = y;
  }
  return x;
}

double GridRayCaster2D::IntersectFallback(int g, const double* o, const double* v) const {
  switch (model_->geom_type[g]) {
    case mjGEOM_MESH:
      return mj_rayMesh(model_, data_, g, o, v);
    case mjGEOM_HFIELD:
      return mj_rayHfield(model_, data_, g, o, v);
    default:
      return mju_rayGeom(data_->geom_xpos + 3 * g, data_->geom_xmat + 9 * g,
                         model_->geom_size + 3 * g, o, v, model_->geom_type[g]);
  }
}

bool GridRayCaster2D::Cast(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W,
                           double max_range_m, RayHit* hit) const {
  return CastRay(origin_W, dir_W, max_range_m, /*with_normal=*/true, hit);
}

bool GridRayCaster2D::CastWithoutNormal(const Eigen::Vector3d& origin_W,
                                        const Eigen::Vector3d& dir_W, double max_range_m,
                                        RayHit* hit) const {
  return CastRay(origin_W, dir_W, max_range_m, /*with_normal=*/false, hit);
}

void GridRayCaster2D::CastBatch(const Eigen::Vector3d* origins_W, const Eigen::Vector3d* dirs_W,
                                int count, double max_range_m, bool with_normal, RayHit* hits,
                                bool* found) const {
  CastRays(origins_W, 1, dirs_W, count, max_range_m, with_normal, hits, found);
}

void GridRayCaster2D::CastFanWithoutNormal(const Eigen::Vector3d& origin_W,
                                           const Eigen::Vector3d* dirs_W, int count,
                                           double max_range_m, RayHit* hits, bool* found) const {
  CastRays(&origin_W, 0, dirs_W, count, max_range_m, /*with_normal=*/false, hits, found);
}

void GridRayCaster2D::CastRays(const Eigen::Vector3d* origins_W, int origin_step,
                               const Eigen::Vector3d* dirs_W, int count, double max_range_m,
                               bool with_normal, RayHit* hits, bool* found) const {
  if (count <= 0) return;
  // The origins' bounding box; a scan's beams share one origin, which is then the box.
  double box_lo[3], box_hi[3];
  for (int k = 0; k < 3; ++k) box_lo[k] = box_hi[k] = origins_W[0][k];
  bool finite = origins_W[0].allFinite();
  int i0 = origin_step == 0 ? count : 1;
  while (i0 < count && origins_W[i0] == origins_W[0]) ++i0;
  for (int i = i0; i < count; ++i) {
    finite = finite && origins_W[i * origin_step].allFinite();
    for (int k = 0; k < 3; ++k) {
      box_lo[k] = std::min(box_lo[k], origins_W[i * origin_step][k]);
      box_hi[k] = std::max(box_hi[k], origins_W[i * origin_step][k]);
    }
  }
  if (nx_ == 0 || !finite || !(max_range_m >= 0.0) || !std::isfinite(max_range_m)) {
    for (int i = 0; i < count; ++i) {
      found[i] = CastRay(origins_W[i * origin_step], dirs_W[i], max_range_m, with_normal, &hits[i]);
    }
    return;
  }
  // The origins' centre (exactly the origin when all are equal) and radius in the floor plane.
  const double o[2] = {0.5 * (box_lo[0] + box_hi[0]), 0.5 * (box_lo[1] + box_hi[1])};
  double radius = 0.0;
  if (i0 < count) {
    double radius_squared = 0.0;
    for (int i = 0; i < count; ++i) {
      const double dx = origins_W[i * origin_step].x() - o[0],
                   dy = origins_W[i * origin_step].y() - o[1];
      radius_squared = std::max(radius_squared, dx * dx + dy * dy);
    }
    // Padded for the rounding of the square and its root.
    radius = std::sqrt(radius_squared) * (1.0 + 1e-9) + 1e-12;
  }
  FanScratch& f = ThreadFanScratch();
  const uint32_t num_shapes = static_cast<uint32_t>(shapes_.size());
  if (f.stamp.size() < num_shapes) f.stamp.resize(num_shapes, 0);
  if (++f.epoch == 0) {
    std::fill(f.stamp.begin(), f.stamp.end(), 0);
    f.epoch = 1;
  }

  // A shape a horizontal ray from some origin can meet within max_range_m: its distance bound
  // from the origins and its angular interval seen from o.
  const auto collect = [&](uint32_t index) {
    const Shape& s = shapes_[index];
    if (s.z_max < box_lo[2] || s.z_min > box_hi[2]) return;
    const Footprint& fp = footprints_[index];
    const double ox = o[0] - fp.centre[0], oy = o[1] - fp.centre[1];
    const double lx = ox * fp.axis_x[0] + oy * fp.axis_x[1];
    const double ly = ox * fp.axis_y[0] + oy * fp.axis_y[1];
    const double dx = std::max(0.0, std::abs(lx) - fp.half[0]);
    const double dy = std::max(0.0, std::abs(ly) - fp.half[1]);
    const double d = std::sqrt(dx * dx + dy * dy);
    FanCandidate c;
    c.min_d = d - radius - kFanDistanceSlackM;
    c.shape = index;
    if (c.min_d > max_range_m) return;
    if (d < kFanNearM + radius) {
      c.lo = 0.0;
      c.hi = 4.0;
    } else {
      const double k0 = DiamondAngle(fp.corner[0][0] - o[0], fp.corner[0][1] - o[1]);
      double lo = 0.0, hi = 0.0;
      for (int j = 1; j < 4; ++j) {
        double delta = DiamondAngle(fp.corner[j][0] - o[0], fp.corner[j][1] - o[1]) - k0;
        if (delta > 2.0) {
          delta -= 4.0;
        } else if (delta <= -2.0) {
          delta += 4.0;
        }
        lo = std::min(lo, delta);
        hi = std::max(hi, delta);
      }
      // From an origin p within `radius` of o, a footprint point q is seen at most
      // asin(radius / |q - o|) away from where o sees it (the angle at q of the triangle o p q;
      // |q - o| >= d > radius), and asin(x) <= x / sqrt(1 - x^2) (its tangent) for x = radius / d.
      // DiamondAngle changes by at most 1 per radian.
      const double x = radius / d;
      const double widen = radius > 0.0 ? x / std::sqrt(1.0 - x * x) : 0.0;
      c.lo = k0 + lo - widen - kFanAngleSlack;
      c.hi = k0 + hi + widen + kFanAngleSlack;
      if (c.hi - c.lo >= 4.0) {
        c.lo = 0.0;
        c.hi = 4.0;
      }
    }
    f.candidates.push_back(c);
  };
  const auto for_each_piece = [](const FanCandidate& c, auto&& piece) {
    if (c.lo < 0.0) {
      piece(c.lo + 4.0, 4.0);
      piece(0.0, c.hi);
    } else if (c.hi >= 4.0) {
      piece(c.lo, 4.0);
      piece(0.0, c.hi - 4.0);
    } else {
      piece(c.lo, c.hi);
    }
  };

  // Sorts the candidates collected last and bins them (count, then fill), nearest first within
  // each bin; then `ray` tests its bin's shapes whose interval holds its direction, nearest first,
  // until one is farther than its nearest hit.
  const auto sort_and_bin = [&] {
    std::sort(f.candidates.begin(), f.candidates.end(),
              [](const FanCandidate& a, const FanCandidate& b) { return a.min_d < b.min_d; });
    f.bin_begin.assign(kFanBins + 1, 0);
    for (const FanCandidate& c : f.candidates) {
      for_each_piece(c, [&](double lo, double hi) {
        for (int b = FanBin(lo), end = FanBin(hi); b <= end; ++b) ++f.bin_begin[b + 1];
      });
    }
    for (int b = 0; b < kFanBins; ++b) f.bin_begin[b + 1] += f.bin_begin[b];
    f.entries.resize(f.bin_begin[kFanBins]);
    f.bin_fill.assign(f.bin_begin.begin(), f.bin_begin.end() - 1);
    for (const FanCandidate& c : f.candidates) {
      for_each_piece(c, [&](double lo, double hi) {
        for (int b = FanBin(lo), end = FanBin(hi); b <= end; ++b) {
          f.entries[f.bin_fill[b]++] = {lo, hi, c.min_d, c.shape};
        }
      });
    }
  };
  const Shape* shapes = shapes_.data();
  const auto test_binned = [&](const double* ray_o, const double* v, double key, NearestHit* ray) {
    const FanEntry* entries = f.entries.data();
    const int bin = FanBin(key);
    NearestHit nearest = *ray;
    for (uint32_t k = f.bin_begin[bin], end = f.bin_begin[bin + 1]; k < end; ++k) {
      const FanEntry& e = entries[k];
      if (e.min_d > nearest.t) break;
      if (key < e.lo || key > e.hi) continue;
      const Shape& s = shapes[e.shape];
      nearest.Consider(IntersectShape(s, ray_o, v, /*horizontal=*/true), s.geom_id);
    }
    *ray = nearest;
  };
  // The shapes of a block of cells: a row's cells are consecutive in the compressed lists, so a
  // row is one run of items.
  const auto collect_cells = [&](int ix0, int ix1, int iy0, int iy1) {
    const uint32_t* cell_begin = cell_begin_.data();
    const uint32_t* cell_items = cell_items_.data();
    uint32_t* stamp = f.stamp.data();
    for (int iy = iy0; iy <= iy1; ++iy) {
      const int row = iy * nx_;
      for (uint32_t k = cell_begin[row + ix0], end = cell_begin[row + ix1 + 1]; k < end; ++k) {
        const uint32_t index = cell_items[k];
        if (stamp[index] == f.epoch) continue;
        stamp[index] = f.epoch;
        collect(index);
      }
    }
  };
  const auto collect_all = [&] {
    for (uint32_t i = 0; i < num_shapes; ++i) {
      if (f.stamp[i] == f.epoch) continue;
      f.stamp[i] = f.epoch;
      collect(i);
    }
  };

  // First the shapes within kFanFirstReachM of every origin: the cells under the square of that
  // reach about o (or every shape, when the cells outnumber them). A ray whose nearest hit is
  // nearer than that reach is final: every shape it could meet nearer has a cell in the square and
  // was tested. Most rays end there, at the walls around the robot.
  const double first = std::min(kFanFirstReachM, max_range_m);
  bool all_collected = false;
  f.candidates.clear();
  {
    const double half = first + radius + kPadM;
    const double gx0 = std::floor((o[0] - half - x0_) * inv_cell_);
    const double gx1 = std::floor((o[0] + half - x0_) * inv_cell_);
    const double gy0 = std::floor((o[1] - half - y0_) * inv_cell_);
    const double gy1 = std::floor((o[1] + half - y0_) * inv_cell_);
    if (gx1 >= 0 && gy1 >= 0 && gx0 <= nx_ - 1 && gy0 <= ny_ - 1) {
      const int ix0 = static_cast<int>(std::max(gx0, 0.0));
      const int ix1 = static_cast<int>(std::min(gx1, nx_ - 1.0));
      const int iy0 = static_cast<int>(std::max(gy0, 0.0));
      const int iy1 = static_cast<int>(std::min(gy1, ny_ - 1.0));
      if ((ix1 - ix0 + 1.0) * (iy1 - iy0 + 1.0) >= num_shapes) {
        collect_all();
        all_collected = true;
      } else {
        collect_cells(ix0, ix1, iy0, iy1);
      }
    }
  }
  sort_and_bin();
  f.pending.clear();
  const double first_final = first < max_range_m ? first - kFanFinalSlackM : kInf;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d dir_W = LevelledDirection(dirs_W[i]);
    const double* v = dir_W.data();
    if (v[2] != 0.0 || (v[0] == 0.0 && v[1] == 0.0)) {
      found[i] = CastRay(origins_W[i * origin_step], dirs_W[i], max_range_m, with_normal, &hits[i]);
      continue;
    }
    const double* ray_o = origins_W[i * origin_step].data();
    NearestHit nearest;
    for (int g : fallback_horizontal_) nearest.Consider(IntersectFallback(g, ray_o, v), g);
    const double key = DiamondAngle(v[0], v[1]);
    test_binned(ray_o, v, key, &nearest);
    if (!all_collected && !(nearest.t < first_final)) {
      f.pending.push_back({dir_W, key, nearest, static_cast<uint32_t>(i)});
      continue;
    }
    found[i] = nearest.Report(max_range_m, &hits[i]);
    if (found[i] && with_normal) SetNormal(origins_W[i * origin_step], dir_W, &hits[i]);
  }

  // Then reach by reach for the rays left: the shapes under the stretch [covered, reach] of every
  // such ray's path (the cells under the bounding box of that stretch of the ray's angular bin,
  // padded by `radius`), and again a ray whose nearest hit is nearer than the reach covered so far
  // is final. Each ray so gets the very hit a single collection of every shape within max_range_m
  // of the origins would give, and shapes behind the walls that end most rays are never
  // collected: the cost does not grow with the world beyond them.
  const FanBinDirections& bin_dirs = TheFanBinDirections();
  double covered = first;
  PendingRay* pending = f.pending.data();
  int num_pending = static_cast<int>(f.pending.size());
  for (double reach = first * kFanReachGrowth; num_pending > 0; reach *= kFanReachGrowth) {
    const bool last = reach >= max_range_m;
    const double next = last ? max_range_m : reach;
    f.candidates.clear();
    if (!all_collected) {
      bool used[kFanBins] = {};
      for (int k = 0; k < num_pending; ++k) used[FanBin(pending[k].key)] = true;
      // A bin's sector never holds an axis direction inside it, so the box of its stretch is
      // that of the four corners; padded for the origins' spread and the points' rounding.
      double cells = 0.0;
      const double pad = radius + kPadM;
      for (int b = 0; b < kFanBins; ++b) {
        if (!used[b]) continue;
        double lo[2], hi[2];
        for (int k = 0; k < 2; ++k) {
          const double c0 = o[k] + covered * bin_dirs.dir[b][k];
          const double c1 = o[k] + covered * bin_dirs.dir[b + 1][k];
          const double c2 = o[k] + next * bin_dirs.dir[b][k];
          const double c3 = o[k] + next * bin_dirs.dir[b + 1][k];
          lo[k] = std::min({c0, c1, c2, c3}) - pad;
          hi[k] = std::max({c0, c1, c2, c3}) + pad;
        }
        const double gx0 = std::floor((lo[0] - x0_) * inv_cell_);
        const double gx1 = std::floor((hi[0] - x0_) * inv_cell_);
        const double gy0 = std::floor((lo[1] - y0_) * inv_cell_);
        const double gy1 = std::floor((hi[1] - y0_) * inv_cell_);
        if (gx1 < 0 || gy1 < 0 || gx0 > nx_ - 1 || gy0 > ny_ - 1) {
          used[b] = false;
          continue;
        }
        FanBox& box = f.boxes[b];
        box.ix0 = static_cast<int>(std::max(gx0, 0.0));
        box.ix1 = static_cast<int>(std::min(gx1, nx_ - 1.0));
        box.iy0 = static_cast<int>(std::max(gy0, 0.0));
        box.iy1 = static_cast<int>(std::min(gy1, ny_ - 1.0));
        cells += (box.ix1 - box.ix0 + 1.0) * (box.iy1 - box.iy0 + 1.0);
      }
      if (cells >= num_shapes) {
        collect_all();
        all_collected = true;
      } else {
        for (int b = 0; b < kFanBins; ++b) {
          if (!used[b]) continue;
          collect_cells(f.boxes[b].ix0, f.boxes[b].ix1, f.boxes[b].iy0, f.boxes[b].iy1);
        }
      }
    }
    if (!f.candidates.empty()) {
      sort_and_bin();
      for (int p = 0; p < num_pending; ++p) {
        PendingRay& ray = pending[p];
        test_binned(origins_W[ray.index * origin_step].data(), ray.dir.data(), ray.key,
                    &ray.nearest);
      }
    }
    covered = next;
    const bool done = last || all_collected;
    // Final: a nearest hit short of the covered stretch by more than the cells' padding.
    int kept = 0;
    for (int p = 0; p < num_pending; ++p) {
      PendingRay& ray = pending[p];
      if (!done && !(ray.nearest.t < covered - kFanFinalSlackM)) {
        pending[kept++] = ray;
        continue;
      }
      const int i = static_cast<int>(ray.index);
      found[i] = ray.nearest.Report(max_range_m, &hits[i]);
      if (found[i] && with_normal) SetNormal(origins_W[i * origin_step], ray.dir, &hits[i]);
    }
    num_pending = kept;
  }
}

void GridRayCaster2D::SetNormal(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W,
                                RayHit* hit) const {
  hit->normal_W = SurfaceNormal(model_, data_, hit->geom_id, origin_W + hit->distance_m * dir_W);
  if (hit->normal_W.x() == 0 && hit->normal_W.y() == 0 && hit->normal_W.z() == 0) {
    hit->normal_W = -dir_W;  // meshes, height fields
  }
}

bool GridRayCaster2D::CastRay(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& given_dir_W,
                              double max_range_m, bool with_normal, RayHit* hit) const {
  const Eigen::Vector3d dir_W = LevelledDirection(given_dir_W);
  const double* o = origin_W.data();
  const double* v = dir_W.data();
  const bool horizontal = v[2] == 0.0;

  NearestHit nearest;
  for (int g : horizontal ? fallback_horizontal_ : fallback_all_) {
    nearest.Consider(IntersectFallback(g, o, v), g);
  }

  // Clip the ray's floor-plane projection to the grid rectangle.
  double t_in = 0.0, t_far = std::min(max_range_m, nearest.t);
  const double lo[2] = {x0_, y0_};
  const double hi[2] = {x0_ + nx_ * cell_m_, y0_ + ny_ * cell_m_};
  bool inside = nx_ > 0;
  for (int k = 0; k < 2 && inside; ++k) {
    if (v[k] == 0.0) {
      inside = o[k] >= lo[k] && o[k] <= hi[k];
    } else {
      const double inv = 1.0 / v[k];
      double ta = (lo[k] - o[k]) * inv, tb = (hi[k] - o[k]) * inv;
      if (ta > tb) std::swap(ta, tb);
      t_in = std::max(t_in, ta);
      t_far = std::min(t_far, tb);
      inside = t_in <= t_far + kStopSlackM;
    }
  }

  if (inside) {
    // Amanatides-Woo: the cell of the entry point, the ray parameter t at which the next x and y
    // cell boundaries are crossed, and the t spacing of those boundaries.
    const double px = o[0] + t_in * v[0], py = o[1] + t_in * v[1];
    int ix = std::clamp(static_cast<int>(std::floor((px - x0_) * inv_cell_)), 0, nx_ - 1);
    int iy = std::clamp(static_cast<int>(std::floor((py - y0_) * inv_cell_)), 0, ny_ - 1);
    const int step_x = v[0] > 0 ? 1 : -1, step_y = v[1] > 0 ? 1 : -1;
    double t_max_x = kInf, t_max_y = kInf, dt_x = kInf, dt_y = kInf;
    if (v[0] != 0.0) {
      t_max_x = (x0_ + (ix + (v[0] > 0 ? 1 : 0)) * cell_m_ - o[0]) / v[0];
      dt_x = cell_m_ / std::abs(v[0]);
    }
    if (v[1] != 0.0) {
      t_max_y = (y0_ + (iy + (v[1] > 0 ? 1 : 0)) * cell_m_ - o[1]) / v[1];
      dt_y = cell_m_ / std::abs(v[1]);
    }
    // Walls span many cells: a small ring of recently tested shapes skips re-testing them (a
    // re-test cannot change the answer).
    constexpr int kRecent = 4;
    uint32_t recent[kRecent];
    std::fill(recent, recent + kRecent, UINT32_MAX);
    int recent_next = 0;
    const uint32_t* cell_begin = cell_begin_.data();
    const uint32_t* cell_items = cell_items_.data();
    const Shape* shapes = shapes_.data();
    const int nx = nx_, ny = ny_;
    for (;;) {
      const double t_out = std::min(t_max_x, t_max_y);
      double z_lo = o[2], z_hi = o[2];
      if (!horizontal) {
        const double z_a = o[2] + t_in * v[2];
        const double z_b = o[2] + std::min(t_out, std::min(max_range_m, nearest.t)) * v[2];
        z_lo = std::min(z_a, z_b);
        z_hi = std::max(z_a, z_b);
      }
      const int cell = iy * nx + ix;
      for (uint32_t k = cell_begin[cell], end = cell_begin[cell + 1]; k < end; ++k) {
        const uint32_t index = cell_items[k];
        const Shape& s = shapes[index];
        if (s.z_max < z_lo || s.z_min > z_hi) continue;
        static_assert(kRecent == 4);
        if ((recent[0] == index) | (recent[1] == index) | (recent[2] == index) |
            (recent[3] == index)) {
          continue;
        }
        recent[recent_next] = index;
        recent_next = (recent_next + 1) & (kRecent - 1);
        nearest.Consider(IntersectShape(s, o, v, horizontal), s.geom_id);
      }
      if (std::min(nearest.t, max_range_m) <= t_out + kStopSlackM) break;
      if (t_max_x < t_max_y) {
        ix += step_x;
        if (ix < 0 || ix >= nx) break;
        t_in = t_max_x;
        t_max_x += dt_x;
      } else {
        iy += step_y;
        if (iy < 0 || iy >= ny) break;
        t_in = t_max_y;
        t_max_y += dt_y;
      }
    }
  }

  if (!nearest.Report(max_range_m, hit)) return false;
  if (with_normal) SetNormal(origin_W, dir_W, hit);
  return true;
}

}  // namespace plywood::sim
