#pragma once

#include <mujoco/mujoco.h>

namespace plywood::sim {

// MuJoCo's own rules for which geom pairs may collide, for the places that decide pairs without
// MuJoCo's broad phase (an installed contact filter replaces them; explicit pairs and the planar
// drive bypass them). Inline: the contact filter calls them ~350 times a step.

// contype / conaffinity: one geom's type bits must meet the other's affinity bits.
inline bool ContactBitsMatch(const mjModel* m, int geom1, int geom2) {
  return (m->geom_contype[geom1] & m->geom_conaffinity[geom2]) ||
         (m->geom_contype[geom2] & m->geom_conaffinity[geom1]);
}

// Bodies welded together never collide, nor (unless disabled) a body with its parent. `weld1` and
// `weld2` are the geoms' body_weldid.
inline bool WeldedOrParentPair(const mjModel* m, int weld1, int weld2) {
  if (weld1 == weld2) return true;
  if (m->opt.disableflags & mjDSBL_FILTERPARENT) return false;
  const int parent1 = m->body_weldid[m->body_parentid[weld1]];
  const int parent2 = m->body_weldid[m->body_parentid[weld2]];
  return (weld1 != 0 && parent2 == weld1) || (weld2 != 0 && parent1 == weld2);
}

}  // namespace plywood::sim
