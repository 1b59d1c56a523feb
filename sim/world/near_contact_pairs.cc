#include "sim/world/near_contact_pairs.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/world/mujoco_pair_rules.h"

namespace plywood::sim {
namespace {

// Covers rounding in the robot's bounding circle; the robot's motion needs none, as the query uses
// the very qpos that MuJoCo's collision pass reads.
constexpr double kSlackM = 0.05;
// Grid cells this size hold a handful of walls' bounding squares each in rooms of a few metres.
constexpr double kCellM = 1.0;
constexpr int kMaxCells = 1 << 20;

bool CanCollide(const mjModel* m, int g1, int g2) {
  if (!ContactBitsMatch(m, g1, g2)) return false;
  const int b1 = m->geom_bodyid[g1], b2 = m->geom_bodyid[g2];
  if (WeldedOrParentPair(m, m->body_weldid[b1], m->body_weldid[b2])) return false;
  const int lo = std::min(b1, b2), hi = std::max(b1, b2);
  const int signature = ((lo + 1) << 16) + hi + 1;
  for (int i = 0; i < m->nexclude; ++i) {
    if (m->exclude_signature[i] == signature) return false;
  }
  return true;
}

// The grid cell of coordinate `v`, clamped to [0, n - 1] before the cast to int: a robot or a geom
// far outside the grid (a spawn at x = 1e300) would overflow it.
int ClampedCell(double v, double origin, double cell_m, int n) {
  return static_cast<int>(std::clamp(std::floor((v - origin) / cell_m), 0.0, n - 1.0));
}

}  // namespace

bool NearContactPairs::Within(const Footprint& f, double x, double y, double reach_m) {
  const double dx = x - f.cx, dy = y - f.cy;
  if (!f.rectangle) {
    const double limit = f.radius + reach_m;
    return dx * dx + dy * dy <= limit * limit;
  }
  // The rectangle's own axes: x along (ux, uy), y along (-uy, ux).
  const double ex = std::max(0.0, std::abs(dx * f.ux + dy * f.uy) - f.half_x);
  const double ey = std::max(0.0, std::abs(-dx * f.uy + dy * f.ux) - f.half_y);
  return ex * ex + ey * ey <= reach_m * reach_m;
}

NearContactPairs::NearContactPairs(mjModel* model, const mjData* data, int robot_base_body)
    : model_(model) {
  mjModel* m = model;
  if (m->npair != kCapacity) {
    throw std::invalid_argument("NearContactPairs: the model must hold the placeholder pairs");
  }
  const int joint = m->body_jntadr[robot_base_body];
  if (joint < 0 || m->jnt_type[joint] != mjJNT_FREE) {
    throw std::invalid_argument("NearContactPairs: the robot base must carry a free joint");
  }
  base_qpos_ = m->jnt_qposadr[joint];
  placeholder_.world_geom = m->pair_geom1[0];
  placeholder_.robot_geom = m->pair_geom2[0];
  placeholder_.dim = m->pair_dim[0];
  std::copy(m->pair_friction, m->pair_friction + 5, placeholder_.friction);
  std::copy(m->pair_solref, m->pair_solref + mjNREF, placeholder_.solref);
  std::copy(m->pair_solimp, m->pair_solimp + mjNIMP, placeholder_.solimp);
  placeholder_.margin = m->pair_margin[0];
  placeholder_.gap = m->pair_gap[0];

  const auto in_robot = [&](int g) { return m->body_rootid[m->geom_bodyid[g]] == robot_base_body; };
  const auto collides = [&](int g) { return m->geom_contype[g] || m->geom_conaffinity[g]; };
  const mjtNum* base_pos = data->xpos + 3 * robot_base_body;
  double max_margin = 0.0;
  for (int g = 0; g < m->ngeom; ++g) max_margin = std::max(max_margin, m->geom_margin[g]);
  for (int g = 0; g < m->ngeom; ++g) {
    if (!in_robot(g) || !collides(g)) continue;
    robot_geoms_.push_back(g);
    const mjtNum* p = data->geom_xpos + 3 * g;
    reach_m_ =
        std::max(reach_m_, std::hypot(p[0] - base_pos[0], p[1] - base_pos[1], p[2] - base_pos[2]) +
                               m->geom_rbound[g]);
  }
  reach_m_ += max_margin + kSlackM;

  // Each candidate pair with the parameters MuJoCo's dynamic search would give its contacts.
  pairs_of_world_geom_.resize(m->ngeom);
  geom_box_.assign(4 * static_cast<size_t>(m->ngeom), 0.0);
  footprints_.assign(m->ngeom, Footprint{});
  std::vector<int> gridded;
  for (int w = 0; w < m->ngeom; ++w) {
    if (in_robot(w) || !collides(w)) continue;
    for (const int robot_geom : robot_geoms_) {
      if (!CanCollide(m, w, robot_geom)) continue;
      PairParameters p{};
      p.world_geom = w;
      p.robot_geom = robot_geom;
      p.robot_body = m->geom_bodyid[robot_geom];
      p.margin = std::max(m->geom_margin[w], m->geom_margin[robot_geom]);
      p.gap = std::max(m->geom_gap[w], m->geom_gap[robot_geom]);
      const int pw = m->geom_priority[w], pr = m->geom_priority[robot_geom];
      if (pw != pr) {
        const int g = pw > pr ? w : robot_geom;
        p.dim = m->geom_condim[g];
        std::copy(m->geom_solref + mjNREF * g, m->geom_solref + mjNREF * (g + 1), p.solref);
        std::copy(m->geom_solimp + mjNIMP * g, m->geom_solimp + mjNIMP * (g + 1), p.solimp);
        const mjtNum* f = m->geom_friction + 3 * g;
        const mjtNum friction[5] = {f[0], f[0], f[1], f[2], f[2]};
        std::copy(friction, friction + 5, p.friction);
      } else {
        p.dim = std::max(m->geom_condim[w], m->geom_condim[robot_geom]);
        const mjtNum s1 = m->geom_solmix[w], s2 = m->geom_solmix[robot_geom];
        mjtNum mix = 0.5;
        if (s1 >= mjMINVAL && s2 >= mjMINVAL) {
          mix = s1 / (s1 + s2);
        } else if (s1 < mjMINVAL && s2 >= mjMINVAL) {
          mix = 0.0;
        } else if (s1 >= mjMINVAL && s2 < mjMINVAL) {
          mix = 1.0;
        }
        const mjtNum* ref1 = m->geom_solref + mjNREF * w;
        const mjtNum* ref2 = m->geom_solref + mjNREF * robot_geom;
        for (int i = 0; i < mjNREF; ++i) {
          p.solref[i] = ref1[0] > 0 && ref2[0] > 0 ? mix * ref1[i] + (1 - mix) * ref2[i]
                                                   : std::min(ref1[i], ref2[i]);
        }
        const mjtNum* imp1 = m->geom_solimp + mjNIMP * w;
        const mjtNum* imp2 = m->geom_solimp + mjNIMP * robot_geom;
        for (int i = 0; i < mjNIMP; ++i) p.solimp[i] = mix * imp1[i] + (1 - mix) * imp2[i];
        const mjtNum* f1 = m->geom_friction + 3 * w;
        const mjtNum* f2 = m->geom_friction + 3 * robot_geom;
        const mjtNum friction[5] = {std::max(f1[0], f2[0]), std::max(f1[0], f2[0]),
                                    std::max(f1[1], f2[1]), std::max(f1[2], f2[2]),
                                    std::max(f1[2], f2[2])};
        std::copy(friction, friction + 5, p.friction);
      }
      pairs_of_world_geom_[w].push_back(p);
    }
    if (pairs_of_world_geom_[w].empty()) continue;
    const bool is_static = m->body_weldid[m->geom_bodyid[w]] == 0;
    const double radius = m->geom_rbound[w];
    if (!is_static) moving_world_geoms_ = true;
    const mjtNum* c = data->geom_xpos + 3 * w;
    // A geom beyond any room's size (an absurd MJCF) is not gridded either: its cell indices
    // would not fit an int; MuJoCo tests it every step, as it always did.
    constexpr double kGriddedLimitM = 1e6;
    const bool room_sized = radius < kGriddedLimitM && m->geom_margin[w] < kGriddedLimitM &&
                            std::abs(c[0]) < kGriddedLimitM && std::abs(c[1]) < kGriddedLimitM;
    if (!is_static || !(radius > 0.0) || !room_sized) {
      always_.push_back(w);  // planes, height fields, moving bodies, absurd sizes
      continue;
    }
    // Footprint on the floor: the exact rectangle of an upright box, the disc of an upright
    // cylinder, else the bounding disc; grown by the geom's margin.
    const mjtNum* R = data->geom_xmat + 9 * w;
    const mjtNum* size = m->geom_size + 3 * w;
    const bool upright = R[2] == 0 && R[5] == 0;
    Footprint& f = footprints_[w];
    f.cx = c[0];
    f.cy = c[1];
    f.radius = radius + m->geom_margin[w];
    double half_x = f.radius, half_y = f.radius;
    if (upright && m->geom_type[w] == mjGEOM_BOX) {
      f.rectangle = true;
      f.ux = R[0];
      f.uy = R[3];
      f.half_x = size[0] + m->geom_margin[w];
      f.half_y = size[1] + m->geom_margin[w];
      f.radius = 0.0;
      half_x = std::abs(R[0]) * f.half_x + std::abs(R[1]) * f.half_y;
      half_y = std::abs(R[3]) * f.half_x + std::abs(R[4]) * f.half_y;
    } else if (upright && m->geom_type[w] == mjGEOM_CYLINDER) {
      f.radius = size[0] + m->geom_margin[w];
      half_x = half_y = f.radius;
    }
    geom_box_[4 * w] = c[0] - half_x;
    geom_box_[4 * w + 1] = c[1] - half_y;
    geom_box_[4 * w + 2] = c[0] + half_x;
    geom_box_[4 * w + 3] = c[1] + half_y;
    gridded.push_back(w);
  }

  if (!gridded.empty()) {
    double x1 = -HUGE_VAL, y1 = -HUGE_VAL;
    x0_ = y0_ = HUGE_VAL;
    for (int w : gridded) {
      x0_ = std::min(x0_, geom_box_[4 * w]);
      y0_ = std::min(y0_, geom_box_[4 * w + 1]);
      x1 = std::max(x1, geom_box_[4 * w + 2]);
      y1 = std::max(y1, geom_box_[4 * w + 3]);
    }
    cell_m_ = kCellM;
    const auto cells = [&](double extent) {
      return std::max(1, static_cast<int>(std::ceil(extent / cell_m_)));
    };
    while (static_cast<double>(cells(x1 - x0_)) * cells(y1 - y0_) > kMaxCells) cell_m_ *= 2.0;
    nx_ = cells(x1 - x0_);
    ny_ = cells(y1 - y0_);
  }
  const auto range = [&](double lo, double hi, double origin, int n, int* i0, int* i1) {
    *i0 = ClampedCell(lo, origin, cell_m_, n);
    *i1 = ClampedCell(hi, origin, cell_m_, n);
  };
  cell_begin_.assign(static_cast<size_t>(nx_) * ny_ + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::uint32_t> fill(cell_begin_.begin(), cell_begin_.end() - 1);
    if (pass == 1) cell_items_.resize(cell_begin_.back());
    for (int w : gridded) {
      int ix0, ix1, iy0, iy1;
      range(geom_box_[4 * w], geom_box_[4 * w + 2], x0_, nx_, &ix0, &ix1);
      range(geom_box_[4 * w + 1], geom_box_[4 * w + 3], y0_, ny_, &iy0, &iy1);
      for (int iy = iy0; iy <= iy1; ++iy) {
        for (int ix = ix0; ix <= ix1; ++ix) {
          const size_t cell = static_cast<size_t>(iy) * nx_ + ix;
          if (pass == 0) {
            ++cell_begin_[cell + 1];
          } else {
            cell_items_[fill[cell]++] = static_cast<std::uint32_t>(w);
          }
        }
      }
    }
    if (pass == 0) {
      for (size_t c = 1; c < cell_begin_.size(); ++c) cell_begin_[c] += cell_begin_[c - 1];
    }
  }
  stamp_.assign(m->ngeom, 0);
}

void NearContactPairs::WritePair(int slot, const PairParameters& p) {
  mjModel* m = model_;
  m->pair_geom1[slot] = p.world_geom;
  m->pair_geom2[slot] = p.robot_geom;
  m->pair_dim[slot] = p.dim;
  const int b1 = m->geom_bodyid[p.world_geom], b2 = m->geom_bodyid[p.robot_geom];
  m->pair_signature[slot] = ((std::min(b1, b2) + 1) << 16) + std::max(b1, b2) + 1;
  std::copy(p.friction, p.friction + 5, m->pair_friction + 5 * slot);
  std::copy(p.solref, p.solref + mjNREF, m->pair_solref + mjNREF * slot);
  std::copy(p.solimp, p.solimp + mjNIMP, m->pair_solimp + mjNIMP * slot);
  m->pair_margin[slot] = p.margin;
  m->pair_gap[slot] = p.gap;
}

NearContactPairs::Active NearContactPairs::Activate(const mjData* data) {
  mjModel* m = model_;
  const double x = data->qpos[base_qpos_], y = data->qpos[base_qpos_ + 1];
  near_.assign(always_.begin(), always_.end());
  if (nx_ > 0 && ++stamp_now_ == 0) {
    std::fill(stamp_.begin(), stamp_.end(), 0);
    stamp_now_ = 1;
  }
  if (nx_ > 0 && std::isfinite(x) && std::isfinite(y)) {
    const auto cell = [&](double v, double origin, int n) {
      return ClampedCell(v, origin, cell_m_, n);
    };
    const int ix0 = cell(x - reach_m_, x0_, nx_), ix1 = cell(x + reach_m_, x0_, nx_);
    const int iy0 = cell(y - reach_m_, y0_, ny_), iy1 = cell(y + reach_m_, y0_, ny_);
    for (int iy = iy0; iy <= iy1; ++iy) {
      for (int ix = ix0; ix <= ix1; ++ix) {
        const size_t c = static_cast<size_t>(iy) * nx_ + ix;
        for (std::uint32_t k = cell_begin_[c]; k < cell_begin_[c + 1]; ++k) {
          const int w = static_cast<int>(cell_items_[k]);
          if (stamp_[w] == stamp_now_) continue;
          stamp_[w] = stamp_now_;
          if (Within(footprints_[w], x, y, reach_m_)) near_.push_back(w);
        }
      }
    }
  }
  std::sort(near_.begin(), near_.end());
  // MuJoCo's dynamic order: body pairs (world, robot body) by robot body, then world geoms, then
  // the robot body's geoms.
  active_.clear();
  for (size_t b = 0; b < robot_geoms_.size(); ++b) {
    const int body = m->geom_bodyid[robot_geoms_[b]];
    if (b > 0 && body == m->geom_bodyid[robot_geoms_[b - 1]]) continue;
    for (int w : near_) {
      for (const PairParameters& p : pairs_of_world_geom_[w]) {
        if (p.robot_body == body) active_.push_back(&p);
      }
    }
  }
  // Moving world bodies still need MuJoCo's own search among themselves (and it would pair them
  // with the robot too): leave everything to it.
  fell_back_ = moving_world_geoms_ || static_cast<int>(active_.size()) > kCapacity;
  if (fell_back_) {
    m->npair = 0;
    used_slots_ = 0;
    last_pair_count_ = -1;
    return Active(this);
  }
  saved_collision_ = m->opt.collision;
  m->opt.collision = mjCOL_PAIR;
  used_slots_ = static_cast<int>(active_.size());
  for (int i = 0; i < used_slots_; ++i) WritePair(i, *active_[i]);
  m->npair = used_slots_;
  last_pair_count_ = used_slots_;
  return Active(this);
}

void NearContactPairs::Restore() {
  mjModel* m = model_;
  for (int i = 0; i < used_slots_; ++i) WritePair(i, placeholder_);
  used_slots_ = 0;
  m->npair = kCapacity;
  if (!fell_back_) m->opt.collision = saved_collision_;
}

NearContactPairs::Active::~Active() { owner_->Restore(); }

}  // namespace plywood::sim
