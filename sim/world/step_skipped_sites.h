#pragma once

#include <mujoco/mujoco.h>

namespace plywood::sim {

// Whether a step may leave every site where it was: true when nothing in MuJoCo 2.2.2's step
// reads site_xpos / site_xmat, i.e. the model has no sensors (site-attached sensors, rangefinders),
// no tendons (spatial tendons wrap through sites) and only joint actuators (site and
// slider-crank transmissions read sites), and no control, passive or sensor callback is
// installed. Then only the sensors' SitePoseInWorld and the pictures read the sites, and a step
// that places them (~215 instructions each in mj_local2Global: 18 on the P3-DX, 34 on the
// Magellan) places them for nothing at every 10 ms step while the range sensors read them at
// 10 Hz. The shipped robots qualify.
bool StepCanSkipSites(const mjModel* m);

// Sets site_xpos / site_xmat of every site, or of one, from its body's pose in `d` with MuJoCo's
// mj_local2Global, exactly as mj_kinematics places it: after a step that skipped the sites, the
// result is bit for bit what mj_step would have left (body poses do not change between steps).
void PlaceSites(const mjModel* m, mjData* d);
void PlaceSite(const mjModel* m, mjData* d, int site_id);

}  // namespace plywood::sim
