#pragma once

#include <mujoco/mujoco.h>

#include <span>
#include <vector>

namespace plywood::sim {

// The geoms a step need not place: geoms of moving bodies that only pictures read. A geom
// qualifies when it is in geom group `ray_skipped_group` (which the ray casters skip), has contype
// and conaffinity 0 (MuJoCo's filters and TightContactFilter reject every pair with it before its
// pose matters), is named by no explicit <pair>, carries no sensor and no tendon wraps around it,
// and the model has no rangefinder (mj_ray over every geom). The P3-DX's and the Magellan's
// massless visual geoms (wheels, shell, plate, laser body, bump panels) are such geoms: 15 of the
// P3-DX's 20 moving geoms, ~220 instructions each per step in mj_local2Global. Ids ascending.
std::vector<int> DrawOnlyGeoms(const mjModel* m, int ray_skipped_group);

// Sets geom_xpos / geom_xmat of `geoms` from their bodies' poses in `d` with MuJoCo's
// mj_local2Global, exactly as mj_kinematics places them: after a step that skipped them, the
// result is bit for bit what mj_step would have left (body poses do not change between steps).
void PlaceGeoms(const mjModel* m, mjData* d, std::span<const int> geoms);

}  // namespace plywood::sim
