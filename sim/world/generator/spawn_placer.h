#pragma once

#include <Eigen/Core>
#include <vector>

#include "sim/world/generator/footprint_2d.h"
#include "sim/world/generator/generated_world.h"
#include "sim/world/generator/world_rng.h"

namespace plywood::sim::worldgen {

// Room kept between a spawn pose's origin and any geometry beyond the largest robot's reach.
inline constexpr double kSpawnMarginM = 0.06;

// What makes a spawn pose acceptable.
struct SpawnRules {
  double clearance_m = 0.0;       // from the robot's origin to every geom footprint
  int count = 3;                  // spawn poses per world
  double min_separation_m = 0.8;  // between any two spawn poses
  // Seed 000's rig (two LMS 200 back to back) stands on spawn_0: at least this fraction of its
  // rays, at the laser's height, must end on something within the range cut. 0.55 here keeps
  // "at least half" true for rays at any other angles (once the world is turned).
  double rig_range_m = 4.0;
  double rig_height_m = 0.34;
  double rig_min_coverage = 0.55;
  int tries_per_spawn = 400;
};

// The default rules: clearance = LargestRobotReachM() + kSpawnMarginM.
SpawnRules DefaultSpawnRules();

// The distance from `p` to the nearest footprint (infinity when there are none).
double Clearance(const std::vector<Footprint>& footprints, const Eigen::Vector2d& p);

// True when `p` lies inside one of the world's interior outlines.
bool InsideInteriors(const GeneratedWorld& world, const Eigen::Vector2d& p);

// The fraction of 360 rays (1 deg apart) from `p` that meet one of `footprints` within `range_m`.
double RigCoverage(const std::vector<Footprint>& footprints, const Eigen::Vector2d& p,
                   double range_m);

// Why a spawn pose is not acceptable under `rules` ("" when it is): outside every interior, or
// closer to geometry than the clearance.
std::string SpawnDefect(const GeneratedWorld& world, const std::vector<Footprint>& footprints,
                        const Eigen::Vector2d& p, const SpawnRules& rules);

// Draws rules.count spawn poses inside the world's interiors (rejection sampling over their
// bounding box), spawn_0 first with the rig's coverage. Fills world.spawns and world.rig_coverage
// and returns true; false when some pose could not be found (the caller redraws the layout).
bool PlaceSpawns(WorldRng& rng, GeneratedWorld& world, const SpawnRules& rules);

}  // namespace plywood::sim::worldgen
