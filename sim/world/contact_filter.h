#pragma once

#include <mujoco/mujoco.h>

namespace plywood::sim {

// MuJoCo 2.2.2's broad phase keeps a geom pair when their bounding spheres overlap. A 16 m plywood
// wall has an 8 m bounding sphere, so every robot geom is paired with nearly every wall on every
// step and sent to the box-box narrow phase: in the office that is most of the step's cost. This
// filter keeps MuJoCo's weld, parent and contype/conaffinity rules and adds an exact, conservative
// test: a pair is dropped when one geom's bounding sphere (plus the pair's margin) lies entirely
// outside the other, a box or a cylinder. It never drops a pair that could touch, so contacts are
// unchanged (tested against the default). MuJoCo still visits every robot geom x world geom pair
// (its broad phase works per body and the world is one body), so this runs ~350 times a step and
// is kept lean: the geometric test runs first, with early exits.
//
// Scene now gives the robot explicit pairs with the geoms near it (NearContactPairs) and turns
// MuJoCo's dynamic search off while stepping, so this filter serves the fallback cases (worlds with
// moving bodies, a crowd of geoms beyond the pair capacity) and any mj_forward outside Scene.
//
// Installed process-wide as mjcb_contactfilter by InstallTightContactFilter(); stateless, so
// several models and threads can share it.
int TightContactFilter(const mjModel* m, mjData* d, int geom1, int geom2);

void InstallTightContactFilter();

}  // namespace plywood::sim
