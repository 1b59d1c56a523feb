// Family `columns`: a rectangular room with 1-6 round columns (r 0.03-0.3 m) and 0-2 tables on
// four thin legs, at any rotation: round and thin things for line extractors.
#include <cstdio>
#include <numbers>

#include "sim/world/generator/placement.h"
#include "sim/world/generator/wall_builder.h"
#include "sim/world/generator/world_families.h"

namespace plywood::sim::worldgen {

using Eigen::Vector2d;

namespace {

constexpr double kColumnsGapM = 0.15;  // between any two things, and to the walls
constexpr int kTries = 200;

Vector2d RandomPoint(WorldRng& rng, double w, double d) {
  return {rng.Rounded(-w / 2, w / 2, 0.01), rng.Rounded(-d / 2, d / 2, 0.01)};
}

}  // namespace

std::optional<double> DrawColumnsWorld(WorldRng& rng, GeneratedWorld& world) {
  const double w = rng.Rounded(3.0, 8.0, 0.01);
  const double d = rng.Rounded(3.0, 8.0, 0.01);
  const double rotation = rng.Rounded(0.0, 359.9, 0.1);
  const std::vector<Vector2d> outline = {
      {-w / 2, -d / 2}, {w / 2, -d / 2}, {w / 2, d / 2}, {-w / 2, d / 2}};
  AddOutlineWalls(world, outline, std::vector<OutlineEdge>(4));
  world.interiors.push_back(outline);
  world.closed = true;

  const int n_columns = rng.Int(1, 6);
  const int n_tables = rng.Int(0, 2);
  std::vector<std::string> columns, tables;
  for (int i = 0; i < n_columns; ++i) {
    const double r = rng.Rounded(0.03, 0.3, 0.005);
    bool placed = false;
    for (int t = 0; t < kTries && !placed; ++t) {
      const Vector2d c = RandomPoint(rng, w, d);
      if (!Fits(world, Footprint::Disc(c, r), kColumnsGapM)) continue;
      world.AddCylinder("column", "obstacle", c, r, 1.0);
      columns.push_back(JsonNumbers({r, c.x(), c.y()}));
      placed = true;
    }
    if (!placed) return std::nullopt;
  }
  for (int i = 0; i < n_tables; ++i) {
    const Vector2d half(rng.Rounded(0.3, 0.8, 0.01), rng.Rounded(0.2, 0.45, 0.01));
    const double height = rng.Rounded(0.70, 0.76, 0.01);
    const double leg_r = rng.Rounded(0.01, 0.03, 0.001);
    const double inset = rng.Rounded(0.02, 0.08, 0.005);
    bool placed = false;
    for (int t = 0; t < kTries && !placed; ++t) {
      const Vector2d c = RandomPoint(rng, w, d);
      const double yaw = rng.Rounded(0.0, 179.0, 1.0);
      if (!Fits(world, Footprint::Box(c, half, yaw * std::numbers::pi / 180.0), kColumnsGapM))
        continue;
      world.AddTable(c, half, yaw, height, leg_r, inset);
      tables.push_back(JsonObject({{"length_m", JsonNumber(2 * half.x())},
                                   {"width_m", JsonNumber(2 * half.y())},
                                   {"height_m", JsonNumber(height)},
                                   {"leg_radius_m", JsonNumber(leg_r)},
                                   {"leg_inset_m", JsonNumber(inset)},
                                   {"centre_m", JsonNumbers({c.x(), c.y()})},
                                   {"yaw_deg", JsonNumber(yaw)}}));
      placed = true;
    }
    if (!placed) return std::nullopt;
  }
  world.parameters = {{"width_m", JsonNumber(w)},
                      {"depth_m", JsonNumber(d)},
                      {"rotation_deg", JsonNumber(rotation)},
                      {"columns", JsonArray(columns)},
                      {"tables", JsonArray(tables)}};
  char text[160];
  std::snprintf(text, sizeof(text), "%.2f x %.2f m room turned %.1f deg, %d column%s, %d table%s",
                w, d, rotation, n_columns, n_columns > 1 ? "s" : "", n_tables,
                n_tables == 1 ? "" : "s");
  world.summary = text;
  return rotation;
}

}  // namespace plywood::sim::worldgen
