// Family `stubs`: a convex room of 4-5 corners of 60-120 deg, 0-2 corners cut by a chamfer and
// 1-3 short wall stubs standing out of the walls.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "msgs/angle_units.h"
#include "sim/world/generator/behind_opening.h"
#include "sim/world/generator/footprint_2d.h"
#include "sim/world/generator/placement.h"
#include "sim/world/generator/wall_builder.h"
#include "sim/world/generator/world_families.h"

namespace plywood::sim::worldgen {

using Eigen::Vector2d;

namespace {

constexpr double kMinCornerDeg = 60.0, kMaxCornerDeg = 120.0;
constexpr double kMinEdgeM = 1.5;
constexpr double kStubClearanceM = 0.5;  // from a stub to any other geom

// The interior angle at corner i of a counter-clockwise outline, degrees.
double CornerDeg(const std::vector<Vector2d>& p, size_t i) {
  const Vector2d in = p[i] - p[(i + p.size() - 1) % p.size()];
  const Vector2d out = p[(i + 1) % p.size()] - p[i];
  return 180.0 - std::atan2(Cross(in, out), in.dot(out)) * 180.0 / kPi;
}

// A convex outline whose corners all lie in [60, 120] deg and whose edges are >= 1.5 m, with at
// least two corners 10 deg or more off square; nothing after 500 draws.
std::optional<std::vector<Vector2d>> DrawOutline(WorldRng& rng, int n) {
  for (int attempt = 0; attempt < 500; ++attempt) {
    std::vector<Vector2d> p;
    for (int k = 0; k < n; ++k) {
      const double a = 2 * kPi * (k + rng.Uniform(-0.25, 0.25)) / n;
      const double r = rng.Uniform(1.6, 3.6);
      p.emplace_back(std::round(100 * r * std::cos(a)) / 100,
                     std::round(100 * r * std::sin(a)) / 100);
    }
    bool ok = true;
    int skewed = 0;
    for (int k = 0; k < n && ok; ++k) {
      const double corner = CornerDeg(p, k);
      ok = corner >= kMinCornerDeg && corner <= kMaxCornerDeg &&
           (p[(k + 1) % n] - p[k]).norm() >= kMinEdgeM;
      skewed += std::abs(corner - 90.0) >= 10.0;
    }
    if (ok && skewed >= 2 && SignedArea(p) > 0) return p;
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> DrawStubsWorld(WorldRng& rng, GeneratedWorld& world) {
  const int n = rng.Int(4, 5);
  const auto drawn = DrawOutline(rng, n);
  if (!drawn) return std::nullopt;
  std::vector<double> corners;
  for (int k = 0; k < n; ++k) corners.push_back(CornerDeg(*drawn, k));

  // Chamfers: corner k becomes two corners `cut` along its edges.
  std::vector<bool> chamfered(n, false);
  const int n_chamfers = rng.Int(0, 2);
  std::vector<int> order(n);
  for (int k = 0; k < n; ++k) order[k] = k;
  Shuffle(order, rng);
  std::vector<std::string> chamfers;
  std::vector<double> cuts(n, 0.0);
  for (int c = 0; c < n_chamfers; ++c) {
    const int k = order[c];
    const Vector2d& v = (*drawn)[k];
    const double shorter =
        std::min(((*drawn)[(k + n - 1) % n] - v).norm(), ((*drawn)[(k + 1) % n] - v).norm());
    cuts[k] = rng.Rounded(0.2, std::min(0.6, 0.3 * shorter), 0.01);
    chamfered[k] = true;
    chamfers.push_back(JsonNumbers({static_cast<double>(k), cuts[k]}));
  }
  std::vector<Vector2d> outline;
  std::vector<bool> chamfer_edge;  // edge i of `outline` is a chamfer
  for (int k = 0; k < n; ++k) {
    const Vector2d& v = (*drawn)[k];
    if (!chamfered[k]) {
      outline.push_back(v);
      chamfer_edge.push_back(false);
      continue;
    }
    const Vector2d prev = (*drawn)[(k + n - 1) % n], next = (*drawn)[(k + 1) % n];
    outline.push_back(v + cuts[k] * (prev - v).normalized());
    chamfer_edge.push_back(true);
    outline.push_back(v + cuts[k] * (next - v).normalized());
    chamfer_edge.push_back(false);
  }
  const auto edge_geoms = AddOutlineWalls(world, outline, std::vector<OutlineEdge>(outline.size()));
  world.interiors.push_back(outline);
  world.closed = true;

  // Stubs: 18 mm plywood standing square out of a wall's inner face.
  const int n_stubs = rng.Int(1, 3);
  std::vector<std::string> stubs;
  for (int s = 0; s < n_stubs; ++s) {
    bool placed = false;
    for (int t = 0; t < 200 && !placed; ++t) {
      const int e = rng.Int(0, static_cast<int>(outline.size()) - 1);
      if (chamfer_edge[e]) continue;
      const EdgeFrame edge = EdgeFrame::Of(outline, e);
      const double u = rng.Rounded(0.5, edge.length_m - 0.5, 0.01);
      const double length = rng.Rounded(0.2, 0.8, 0.01);
      const Vector2d inward = -edge.outward;
      const Vector2d centre = edge.At(u, 0.0) + inward * (length / 2);
      const double yaw_rad = std::atan2(inward.y(), inward.x());
      const Footprint f = Footprint::Box(centre, {length / 2, kWallThicknessM / 2}, yaw_rad);
      if (!FootprintInsideInteriors(world, f) ||
          DistanceToGeoms(world, f, edge_geoms[e]) < kStubClearanceM) {
        continue;
      }
      world.AddWallBox(centre, length / 2, yaw_rad * 180.0 / kPi);
      stubs.push_back(JsonNumbers({static_cast<double>(e), u, length}));
      placed = true;
    }
    if (!placed) return std::nullopt;
  }
  const double rotation = rng.Rounded(0.0, 359.9, 0.1);
  world.parameters = {{"corners", JsonNumber(n)},
                      {"corner_angles_deg", JsonNumbers(corners)},
                      {"chamfers", JsonArray(chamfers)},
                      {"stubs", JsonArray(stubs)},
                      {"rotation_deg", JsonNumber(rotation)}};
  char text[160];
  std::snprintf(text, sizeof(text), "%d-cornered room, %d chamfer%s, %d wall stub%s", n, n_chamfers,
                n_chamfers == 1 ? "" : "s", n_stubs, n_stubs == 1 ? "" : "s");
  world.summary = text;
  return rotation;
}

}  // namespace plywood::sim::worldgen
