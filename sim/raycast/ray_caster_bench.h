#pragma once

#include <mujoco/mujoco.h>

#include <cstdint>

namespace plywood::sim {

struct RayCasterBenchResult {
  double mj_ray_us_per_ray = 0.0;  // MujocoRayCaster
  double grid_us_per_ray = 0.0;    // GridRayCaster2D (construction not included)
  int world_geoms = 0;             // geoms rays can see (the robot's excluded)
  int mismatches = 0;  // rays where the casters disagree on hit, geom or distance (expect 0)
};

// Times MujocoRayCaster against GridRayCaster2D on the same `rays` horizontal rays: origins drawn
// uniformly at `height_m` over the world's static footprint, rejecting points inside a geom;
// directions uniform in yaw; ranges capped at `max_range_m` (a SICK LMS 200's 8 m by default).
// Wall-clock figures of one pass each, so run it on an otherwise idle machine.
// @pre mj_forward has run on `data`.
RayCasterBenchResult RunRayCasterBench(const mjModel* model, const mjData* data, int rays,
                                       uint64_t seed, double max_range_m = 8.0,
                                       double height_m = 0.3);

}  // namespace plywood::sim
