#include "sim/world/generator/behind_opening.h"

#include <algorithm>

#include "sim/world/generator/placement.h"
#include "sim/world/generator/wall_builder.h"

namespace plywood::sim::worldgen {
namespace {

using Eigen::Vector2d;

// Keeps `candidate` (world plus new geoms from index `first_new` on) when its new geoms keep
// `gap_m` from the old ones (except `touching`) and stand on no interior.
bool Accept(GeneratedWorld& world, GeneratedWorld& candidate, size_t first_new,
            const std::vector<int>& touching, double gap_m) {
  for (size_t i = first_new; i < candidate.geoms.size(); ++i) {
    const Footprint f = candidate.geoms[i].footprint();
    if (DistanceToGeoms(world, f, touching) < gap_m) return false;
    for (const auto& outline : world.interiors) {
      for (const Vector2d& c : f.corners) {
        if (InsidePolygon(outline, c)) return false;
      }
    }
  }
  world = std::move(candidate);
  return true;
}

}  // namespace

EdgeFrame EdgeFrame::Of(const std::vector<Vector2d>& outline, int edge) {
  EdgeFrame f;
  f.start = outline[edge];
  const Vector2d end = outline[(edge + 1) % outline.size()];
  f.length_m = (end - f.start).norm();
  f.along = (end - f.start) / f.length_m;
  f.outward = Vector2d(f.along.y(), -f.along.x());
  return f;
}

bool AddAlcove(GeneratedWorld& world, const EdgeFrame& edge, double from_m, double to_m,
               double depth_m, const std::vector<int>& edge_geoms, double gap_m) {
  const double t = kWallThicknessM;
  // Counter-clockwise in the world: the (u, v) frame is left-handed.
  std::vector<Vector2d> outline = {edge.At(from_m, t + depth_m), edge.At(to_m, t + depth_m),
                                   edge.At(to_m, t), edge.At(from_m, t)};
  std::vector<OutlineEdge> edges(4);
  edges[2].built = false;  // on the edge wall's outer face
  GeneratedWorld candidate = world;
  const size_t first_new = candidate.geoms.size();
  AddOutlineWalls(candidate, outline, edges);
  candidate.interiors.push_back(outline);
  return Accept(world, candidate, first_new, edge_geoms, gap_m);
}

bool AddPanel(GeneratedWorld& world, const EdgeFrame& edge, double from_m, double to_m,
              double distance_m, double gap_m) {
  const double v = kWallThicknessM + distance_m;
  GeneratedWorld candidate = world;
  const size_t first_new = candidate.geoms.size();
  AddWallAlong(candidate, edge.At(from_m, v), edge.At(to_m, v));
  return Accept(world, candidate, first_new, {}, gap_m);
}

}  // namespace plywood::sim::worldgen
