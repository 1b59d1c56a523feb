#include "sim/contact_filter.h"

#include <algorithm>
#include <cmath>

namespace plywood::sim {
namespace {

// True when `other`'s bounding sphere, grown by `margin`, cannot reach box geom `box`.
bool OutsideBox(const mjModel* m, const mjData* d, int box, int other, mjtNum margin) {
  const mjtNum radius = m->geom_rbound[other];
  if (radius <= 0.0) return false;  // planes (and height fields) have no bounding sphere
  const mjtNum* c = d->geom_xpos + 3 * box;
  const mjtNum* r = d->geom_xmat + 9 * box;  // row-major: columns are the box's axes
  const mjtNum* p = d->geom_xpos + 3 * other;
  const mjtNum* half = m->geom_size + 3 * box;
  const mjtNum delta[3] = {p[0] - c[0], p[1] - c[1], p[2] - c[2]};
  mjtNum outside_squared = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const mjtNum local = delta[0] * r[axis] + delta[1] * r[3 + axis] + delta[2] * r[6 + axis];
    const mjtNum excess = std::max<mjtNum>(std::abs(local) - half[axis], 0.0);
    outside_squared += excess * excess;
  }
  const mjtNum reach = radius + margin;
  return outside_squared > reach * reach;
}

}  // namespace

int TightContactFilter(const mjModel* m, mjData* d, int geom1, int geom2) {
  // MuJoCo's own rules, which an installed filter replaces: bodies welded together never collide,
  // nor (unless disabled) a body with its parent, and contype/conaffinity must match.
  const int body1 = m->body_weldid[m->geom_bodyid[geom1]];
  const int body2 = m->body_weldid[m->geom_bodyid[geom2]];
  if (body1 == body2) return 1;
  if (!(m->opt.disableflags & mjDSBL_FILTERPARENT)) {
    const int parent1 = m->body_weldid[m->body_parentid[body1]];
    const int parent2 = m->body_weldid[m->body_parentid[body2]];
    if ((body1 != 0 && parent2 == body1) || (body2 != 0 && parent1 == body2)) return 1;
  }
  const bool compatible = (m->geom_contype[geom1] & m->geom_conaffinity[geom2]) ||
                          (m->geom_contype[geom2] & m->geom_conaffinity[geom1]);
  if (!compatible) return 1;
  const mjtNum margin = std::max(m->geom_margin[geom1], m->geom_margin[geom2]);
  if (m->geom_type[geom1] == mjGEOM_BOX && OutsideBox(m, d, geom1, geom2, margin)) return 1;
  if (m->geom_type[geom2] == mjGEOM_BOX && OutsideBox(m, d, geom2, geom1, margin)) return 1;
  return 0;
}

void InstallTightContactFilter() { mjcb_contactfilter = TightContactFilter; }

}  // namespace plywood::sim
