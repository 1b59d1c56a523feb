#include "sim/world/generator/spawn_placer.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numbers>

#include "sim/world/generator/robot_reach.h"

namespace plywood::sim::worldgen {

using Eigen::Vector2d;

SpawnRules DefaultSpawnRules() {
  SpawnRules rules;
  rules.clearance_m = LargestRobotReachM() + kSpawnMarginM;
  return rules;
}

double Clearance(const std::vector<Footprint>& footprints, const Vector2d& p) {
  double clearance = std::numeric_limits<double>::infinity();
  for (const Footprint& f : footprints) clearance = std::min(clearance, DistanceToPoint(f, p));
  return clearance;
}

bool InsideInteriors(const GeneratedWorld& world, const Vector2d& p) {
  for (const auto& outline : world.interiors) {
    if (InsidePolygon(outline, p)) return true;
  }
  return false;
}

double RigCoverage(const std::vector<Footprint>& footprints, const Vector2d& p, double range_m) {
  constexpr int kRays = 360;
  int hits = 0;
  for (int k = 0; k < kRays; ++k) {
    const double a = 2.0 * std::numbers::pi * k / kRays;
    const Vector2d direction(std::cos(a), std::sin(a));
    for (const Footprint& f : footprints) {
      const auto t = RayHit(f, p, direction);
      if (t && *t <= range_m) {
        ++hits;
        break;
      }
    }
  }
  return static_cast<double>(hits) / kRays;
}

std::string SpawnDefect(const GeneratedWorld& world, const std::vector<Footprint>& footprints,
                        const Vector2d& p, const SpawnRules& rules) {
  if (!InsideInteriors(world, p)) return "outside the room";
  const double clearance = Clearance(footprints, p);
  if (clearance < rules.clearance_m) {
    return "only " + JsonNumber(clearance) + " m from geometry (needs " +
           JsonNumber(rules.clearance_m) + " m)";
  }
  return "";
}

bool PlaceSpawns(WorldRng& rng, GeneratedWorld& world, const SpawnRules& rules) {
  Eigen::AlignedBox2d box;
  for (const auto& outline : world.interiors) {
    for (const Vector2d& p : outline) box.extend(p);
  }
  const std::vector<Footprint> all = world.Footprints();
  const std::vector<Footprint> at_laser = world.FootprintsAtHeight(rules.rig_height_m);
  world.spawns.clear();
  for (int k = 0; k < rules.count; ++k) {
    bool found = false;
    for (int t = 0; t < rules.tries_per_spawn && !found; ++t) {
      const Vector2d p(rng.Rounded(box.min().x(), box.max().x(), 0.01),
                       rng.Rounded(box.min().y(), box.max().y(), 0.01));
      const double yaw = rng.Rounded(-179, 180, 1);
      if (!SpawnDefect(world, all, p, rules).empty()) continue;
      bool spread = true;
      for (const SpawnPose& s : world.spawns) {
        spread = spread && (p - Vector2d(s.x_m, s.y_m)).norm() >= rules.min_separation_m;
      }
      if (!spread) continue;
      if (k == 0) {
        const double coverage = RigCoverage(at_laser, p, rules.rig_range_m);
        if (coverage < rules.rig_min_coverage) continue;
        world.rig_coverage = coverage;
      }
      world.spawns.push_back({p.x(), p.y(), yaw});
      found = true;
    }
    if (!found) return false;
  }
  return true;
}

}  // namespace plywood::sim::worldgen
