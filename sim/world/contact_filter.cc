#include "sim/world/contact_filter.h"

#include <algorithm>
#include <cmath>

#include "sim/world/mujoco_pair_rules.h"

namespace plywood::sim {
namespace {

// True when `other`'s bounding sphere, grown by `margin`, cannot reach box geom `box`. Called for
// every robot-geom x world-geom pair on every step, so it exits as soon as one box axis separates
// them (the usual case for a wall).
[[gnu::always_inline]] inline bool OutsideBox(const mjModel* m, const mjData* d, int box, int other,
                                              mjtNum margin) {
  const mjtNum radius = m->geom_rbound[other];
  if (radius <= 0.0) return false;  // planes (and height fields) have no bounding sphere
  const mjtNum reach = radius + margin;
  const mjtNum* c = d->geom_xpos + 3 * box;
  const mjtNum* r = d->geom_xmat + 9 * box;  // row-major: columns are the box's axes
  const mjtNum* p = d->geom_xpos + 3 * other;
  const mjtNum* half = m->geom_size + 3 * box;
  const mjtNum dx = p[0] - c[0], dy = p[1] - c[1], dz = p[2] - c[2];
  mjtNum outside_squared = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const mjtNum local = dx * r[axis] + dy * r[3 + axis] + dz * r[6 + axis];
    const mjtNum excess = std::abs(local) - half[axis];
    if (excess <= 0.0) continue;
    if (excess > reach) return true;
    outside_squared += excess * excess;
  }
  return outside_squared > reach * reach;
}

// True when `other`'s bounding sphere, grown by `margin`, cannot reach cylinder geom `cylinder`
// (table legs, columns: a third of the shipped worlds' geoms).
[[gnu::always_inline]] inline bool OutsideCylinder(const mjModel* m, const mjData* d, int cylinder,
                                                   int other, mjtNum margin) {
  const mjtNum radius = m->geom_rbound[other];
  if (radius <= 0.0) return false;
  const mjtNum reach = radius + margin;
  const mjtNum* c = d->geom_xpos + 3 * cylinder;
  const mjtNum* r = d->geom_xmat + 9 * cylinder;  // column 2 is the axis
  const mjtNum* p = d->geom_xpos + 3 * other;
  const mjtNum cylinder_radius = m->geom_size[3 * cylinder];
  const mjtNum half_length = m->geom_size[3 * cylinder + 1];
  const mjtNum dx = p[0] - c[0], dy = p[1] - c[1], dz = p[2] - c[2];
  const mjtNum u = dx * r[0] + dy * r[3] + dz * r[6];
  const mjtNum v = dx * r[1] + dy * r[4] + dz * r[7];
  const mjtNum radial_squared = u * u + v * v;
  const mjtNum radial_limit = cylinder_radius + reach;
  if (radial_squared > radial_limit * radial_limit) return true;
  const mjtNum axial_excess = std::abs(dx * r[2] + dy * r[5] + dz * r[8]) - half_length;
  if (axial_excess <= 0.0) return false;
  if (axial_excess > reach) return true;
  const mjtNum radial_excess = std::max<mjtNum>(std::sqrt(radial_squared) - cylinder_radius, 0.0);
  return radial_excess * radial_excess + axial_excess * axial_excess > reach * reach;
}

// True when the bounding sphere of one geom, grown by `margin`, cannot reach the other's shape.
[[gnu::always_inline]] inline bool Separated(const mjModel* m, const mjData* d, int shape,
                                             int other, mjtNum margin) {
  switch (m->geom_type[shape]) {
    case mjGEOM_BOX:
      return OutsideBox(m, d, shape, other, margin);
    case mjGEOM_CYLINDER:
      return OutsideCylinder(m, d, shape, other, margin);
    default:
      return false;
  }
}

}  // namespace

int TightContactFilter(const mjModel* m, mjData* d, int geom1, int geom2) {
  // Every test below only ever rejects, so their order is free: the geometric one goes first as it
  // settles most robot x wall pairs on its own.
  const mjtNum margin = std::max(m->geom_margin[geom1], m->geom_margin[geom2]);
  if (Separated(m, d, geom1, geom2, margin) || Separated(m, d, geom2, geom1, margin)) return 1;
  // MuJoCo's own rules, which an installed filter replaces: bodies welded together never collide,
  // nor (unless disabled) a body with its parent, and contype/conaffinity must match.
  if (WeldedOrParentPair(m, m->body_weldid[m->geom_bodyid[geom1]],
                         m->body_weldid[m->geom_bodyid[geom2]])) {
    return 1;
  }
  return ContactBitsMatch(m, geom1, geom2) ? 0 : 1;
}

void InstallTightContactFilter() { mjcb_contactfilter = TightContactFilter; }

}  // namespace plywood::sim
