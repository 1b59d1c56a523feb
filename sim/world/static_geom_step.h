#pragma once

#include <mujoco/mujoco.h>

#include <span>

namespace plywood::sim {

// mj_step without recomputing the world body's geom poses, which never change: MuJoCo 2.2.2's
// mj_kinematics sets every geom's geom_xpos / geom_xmat on every step, ~0.3k instructions per
// static geom, so a bigger world made every step slower. The step is MuJoCo's own pipeline (the
// public pieces of mj_step and mj_fwdPosition, in their order); only mj_kinematics' geom loop is
// narrowed to the geoms of the other bodies, each placed by MuJoCo's mj_local2Global exactly as
// mj_kinematics places it. The result is bit-identical to mj_step (static_geom_step_test).
// Falls back to mj_step for integrators other than Euler and when the world body has no geoms;
// after mj_checkPos or mj_checkVel reset the data (bad values), the full position stage runs.
// `m` is modified during the call (ngeom, nsite) and restored before it returns, also on
// exceptions.
// @pre the world body's geom poses in `d` are current: mj_kinematics (or mj_forward, mj_step)
// has run on `d` since it was made or last reset.
void StepWithStaticWorldGeoms(mjModel* m, mjData* d);

// The same step, also leaving the geoms in `unplaced` (ids ascending, none of the world body's;
// see DrawOnlyGeoms) where they were: their geom_xpos / geom_xmat keep their values from before
// the step until PlaceGeoms sets them. Returns true when it skipped them, false when the step fell
// back to a path that placed every geom (mj_step, or the full position stage after a reset).
// Everything else the step computes is bit-identical to mj_step as long as nothing in the step
// reads those geoms' poses (which DrawOnlyGeoms makes sure of). With `skip_sites` (only when
// StepCanSkipSites(m)) every site is left where it was too, until PlaceSites or PlaceSite sets it;
// the return value is then true whenever the step skipped anything.
bool StepWithStaticWorldGeoms(mjModel* m, mjData* d, std::span<const int> unplaced,
                              bool skip_sites = false);

}  // namespace plywood::sim
