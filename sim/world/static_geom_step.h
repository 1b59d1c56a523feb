#pragma once

#include <mujoco/mujoco.h>

namespace plywood::sim {

// mj_step without recomputing the world body's geom poses, which never change: MuJoCo 2.2.2's
// mj_kinematics sets every geom's geom_xpos / geom_xmat on every step, ~0.3k instructions per
// static geom, so a bigger world made every step slower. The step is MuJoCo's own pipeline (the
// public pieces of mj_step and mj_fwdPosition, in their order); only mj_kinematics' geom loop is
// narrowed to the geoms of the other bodies, each placed by MuJoCo's mj_local2Global exactly as
// mj_kinematics places it. The result is bit-identical to mj_step (static_geom_step_test).
// Falls back to mj_step for integrators other than Euler and when the world body has no geoms;
// after mj_checkPos or mj_checkVel reset the data (bad values), the full position stage runs.
// `m` is modified during the call (ngeom) and restored before it returns, also on exceptions.
// @pre the world body's geom poses in `d` are current: mj_kinematics (or mj_forward, mj_step)
// has run on `d` since it was made or last reset.
void StepWithStaticWorldGeoms(mjModel* m, mjData* d);

}  // namespace plywood::sim
