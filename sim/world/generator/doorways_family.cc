// Family `doorways`: a rectangular room with 1-3 openings (0.3-1.2 m) in distinct walls, each with
// nothing, a free-standing panel or a closed alcove behind it.
#include <algorithm>
#include <cstdio>

#include "sim/world/generator/behind_opening.h"
#include "sim/world/generator/placement.h"
#include "sim/world/generator/wall_builder.h"
#include "sim/world/generator/world_families.h"

namespace plywood::sim::worldgen {

using Eigen::Vector2d;

namespace {

constexpr double kMinOpeningM = 0.3, kMaxOpeningM = 1.2;
constexpr double kDoorwayJambM = 0.3;  // shortest wall piece beside an opening

struct Opening {
  int wall = 0;
  double from = 0.0, width = 0.0;
  std::string behind;  // nothing, panel, alcove
};

}  // namespace

std::optional<double> DrawDoorwaysWorld(WorldRng& rng, GeneratedWorld& world) {
  const double w = rng.Rounded(3.0, 7.0, 0.01);
  const double d = rng.Rounded(3.0, 7.0, 0.01);
  const double rotation = rng.Rounded(0.0, 359.9, 0.1);
  const std::vector<Vector2d> outline = {
      {-w / 2, -d / 2}, {w / 2, -d / 2}, {w / 2, d / 2}, {-w / 2, d / 2}};
  std::vector<int> walls = {0, 1, 2, 3};
  Shuffle(walls, rng);
  const int n = rng.Int(1, 3);
  std::vector<Opening> openings;
  std::vector<OutlineEdge> edges(4);
  for (int k = 0; k < n; ++k) {
    Opening o;
    o.wall = walls[k];
    const double length = (outline[(o.wall + 1) % 4] - outline[o.wall]).norm();
    o.width = rng.Rounded(kMinOpeningM, kMaxOpeningM, 0.01);
    o.from = rng.Rounded(kDoorwayJambM, length - kDoorwayJambM - o.width, 0.01);
    o.behind = std::vector<std::string>{"nothing", "panel", "alcove"}[rng.Int(0, 2)];
    edges[o.wall].openings.push_back({o.from, o.from + o.width});
    openings.push_back(o);
  }
  const auto edge_geoms = AddOutlineWalls(world, outline, edges);
  world.interiors.push_back(outline);
  world.closed = true;
  std::vector<std::string> described;
  for (const Opening& o : openings) {
    const EdgeFrame edge = EdgeFrame::Of(outline, o.wall);
    std::vector<WorldParameter> fields = {{"wall", JsonNumber(o.wall)},
                                          {"from_m", JsonNumber(o.from)},
                                          {"width_m", JsonNumber(o.width)},
                                          {"behind", JsonString(o.behind)}};
    if (o.behind == "panel") {
      const double distance = rng.Rounded(0.3, 1.5, 0.01);
      const double overhang = rng.Rounded(0.1, 0.75, 0.01);
      const double from = std::max(0.1, o.from - overhang);
      const double to = std::min(edge.length_m - 0.1, o.from + o.width + overhang);
      if (!AddPanel(world, edge, from, to, distance, 0.3)) return std::nullopt;
      fields.push_back({"panel_distance_m", JsonNumber(distance)});
      fields.push_back({"panel_length_m", JsonNumber(to - from)});
      world.closed = false;
    } else if (o.behind == "alcove") {
      const double depth = rng.Rounded(1.0, 3.0, 0.01);
      // Its side walls stay kDoorwayJambM from the room's corners (and never inside the opening).
      const double from = std::max(kDoorwayJambM, o.from - rng.Rounded(0.0, 1.0, 0.01));
      const double to =
          std::min(edge.length_m - kDoorwayJambM, o.from + o.width + rng.Rounded(0.0, 1.0, 0.01));
      if (!AddAlcove(world, edge, from, to, depth, edge_geoms[o.wall], 0.25)) return std::nullopt;
      fields.push_back({"alcove_depth_m", JsonNumber(depth)});
      fields.push_back({"alcove_width_m", JsonNumber(to - from)});
    } else {
      world.closed = false;
    }
    described.push_back(JsonObject(fields));
  }
  world.parameters = {{"width_m", JsonNumber(w)},
                      {"depth_m", JsonNumber(d)},
                      {"rotation_deg", JsonNumber(rotation)},
                      {"openings", JsonArray(described)}};
  char text[160];
  std::snprintf(text, sizeof(text), "%.2f x %.2f m room turned %.1f deg with %d opening%s", w, d,
                rotation, n, n > 1 ? "s" : "");
  world.summary = text;
  return rotation;
}

}  // namespace plywood::sim::worldgen
