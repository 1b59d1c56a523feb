#include "sim/world/generator/placement.h"

#include <algorithm>
#include <limits>

namespace plywood::sim::worldgen {
namespace {

constexpr double kTouchM = 1e-6;

// Points just inside the footprint's boundary (1 mm in, so a box standing against a wall does not
// depend on how the point-in-polygon test treats its boundary).
std::vector<Eigen::Vector2d> Probes(const Footprint& f) {
  constexpr double kInsetM = 1e-3;
  if (f.shape == Footprint::Shape::kPolygon) {
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const auto& c : f.corners) centre += c / static_cast<double>(f.corners.size());
    std::vector<Eigen::Vector2d> probes;
    for (const auto& c : f.corners) probes.push_back(c + kInsetM * (centre - c).normalized());
    return probes;
  }
  const double r = std::max(0.0, f.radius_m - kInsetM);
  return {f.centre, f.centre + Eigen::Vector2d(r, 0), f.centre + Eigen::Vector2d(-r, 0),
          f.centre + Eigen::Vector2d(0, r), f.centre + Eigen::Vector2d(0, -r)};
}

}  // namespace

double DistanceToGeoms(const GeneratedWorld& world, const Footprint& candidate,
                       const std::vector<int>& skip) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < world.geoms.size(); ++i) {
    if (std::find(skip.begin(), skip.end(), static_cast<int>(i)) != skip.end()) continue;
    best = std::min(best, Distance(candidate, world.geoms[i].footprint()));
  }
  return best;
}

bool FootprintInsideInteriors(const GeneratedWorld& world, const Footprint& candidate) {
  for (const auto& outline : world.interiors) {
    bool inside = true;
    for (const Eigen::Vector2d& p : Probes(candidate)) inside = inside && InsidePolygon(outline, p);
    if (inside) return true;
  }
  return false;
}

bool Fits(const GeneratedWorld& world, const Footprint& candidate, double gap_m) {
  return FootprintInsideInteriors(world, candidate) && DistanceToGeoms(world, candidate) >= gap_m;
}

bool FitsAgainstWalls(const GeneratedWorld& world, const Footprint& candidate, double gap_m) {
  if (!FootprintInsideInteriors(world, candidate)) return false;
  for (const WorldGeom& g : world.geoms) {
    const Footprint f = g.footprint();
    const double d = Distance(candidate, f);
    if (d >= gap_m) continue;
    if (g.geom_class != "wall" || d > kTouchM || Overlap(candidate, f, kTouchM)) return false;
  }
  return true;
}

}  // namespace plywood::sim::worldgen
