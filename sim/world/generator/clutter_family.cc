// Family `clutter`: a rectangular room with 2-8 boxes, each side 0.1-0.6 m, at any yaw.
#include <cstdio>
#include <numbers>

#include "sim/world/generator/placement.h"
#include "sim/world/generator/wall_builder.h"
#include "sim/world/generator/world_families.h"

namespace plywood::sim::worldgen {

using Eigen::Vector2d;

std::optional<double> DrawClutterWorld(WorldRng& rng, GeneratedWorld& world) {
  constexpr double kGapM = 0.05;  // boxes may stand close, never overlap
  constexpr int kTries = 200;
  const double w = rng.Rounded(3.0, 7.0, 0.01);
  const double d = rng.Rounded(3.0, 7.0, 0.01);
  const double rotation = rng.Rounded(0.0, 359.9, 0.1);
  const std::vector<Vector2d> outline = {
      {-w / 2, -d / 2}, {w / 2, -d / 2}, {w / 2, d / 2}, {-w / 2, d / 2}};
  AddOutlineWalls(world, outline, std::vector<OutlineEdge>(4));
  world.interiors.push_back(outline);
  world.closed = true;

  const int n = rng.Int(2, 8);
  std::vector<std::string> boxes;
  for (int i = 0; i < n; ++i) {
    const Vector2d size(rng.Rounded(0.1, 0.6, 0.01), rng.Rounded(0.1, 0.6, 0.01));
    const double height = rng.Rounded(0.4, 1.0, 0.05);
    bool placed = false;
    for (int t = 0; t < kTries && !placed; ++t) {
      const Vector2d c(rng.Rounded(-w / 2, w / 2, 0.01), rng.Rounded(-d / 2, d / 2, 0.01));
      const double yaw = rng.Rounded(0.0, 179.0, 1.0);
      if (!Fits(world, Footprint::Box(c, size / 2, yaw * std::numbers::pi / 180.0), kGapM)) {
        continue;
      }
      world.AddBox("obstacle", "obstacle", c, size / 2, yaw, height);
      boxes.push_back(JsonNumbers({size.x(), size.y(), height, c.x(), c.y(), yaw}));
      placed = true;
    }
    if (!placed) return std::nullopt;
  }
  world.parameters = {{"width_m", JsonNumber(w)},
                      {"depth_m", JsonNumber(d)},
                      {"rotation_deg", JsonNumber(rotation)},
                      {"boxes", JsonArray(boxes)}};
  char text[160];
  std::snprintf(text, sizeof(text), "%.2f x %.2f m room turned %.1f deg with %d boxes", w, d,
                rotation, n);
  world.summary = text;
  return rotation;
}

}  // namespace plywood::sim::worldgen
