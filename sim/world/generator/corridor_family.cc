// Family `corridor`: a straight corridor, an L turn, a T or an X junction, 1-2 m wide, arms
// 1.5-5 m, ends closed or open, 0-3 side openings with an alcove or nothing behind.
#include <algorithm>
#include <cstdio>

#include "sim/world/generator/behind_opening.h"
#include "sim/world/generator/placement.h"
#include "sim/world/generator/wall_builder.h"
#include "sim/world/generator/world_families.h"

namespace plywood::sim::worldgen {

using Eigen::Vector2d;

namespace {

constexpr double kCorridorJambM = 0.3;
const char* const kJunctions[] = {"straight", "L", "T", "X"};
// Arms present per junction, in the order east, north, west, south.
constexpr bool kArms[4][4] = {{true, false, true, false},
                              {true, true, false, false},
                              {true, true, true, false},
                              {true, true, true, true}};

Vector2d Direction(int k) {
  const Vector2d d[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  return d[k];
}

}  // namespace

std::optional<double> DrawCorridorWorld(WorldRng& rng, GeneratedWorld& world) {
  const int junction = rng.Int(0, 3);
  const double width = rng.Rounded(1.0, 2.0, 0.01);
  const double h = width / 2;
  double lengths[4] = {0, 0, 0, 0};
  for (int k = 0; k < 4; ++k) {
    if (kArms[junction][k]) lengths[k] = rng.Rounded(1.5, 5.0, 0.01);
  }
  // Around the centre square counter-clockwise, out along each arm and back.
  std::vector<Vector2d> raw;
  for (int k = 0; k < 4; ++k) {
    const Vector2d d = Direction(k), p = Direction((k + 1) % 4);
    raw.push_back(h * d - h * p);
    if (lengths[k] > 0) {
      raw.push_back((h + lengths[k]) * d - h * p);
      raw.push_back((h + lengths[k]) * d + h * p);
    }
    raw.push_back(h * d + h * p);
  }
  const std::vector<Vector2d> outline = SimplifyOutline(raw);
  const int n = static_cast<int>(outline.size());
  std::vector<int> arm_end(n, -1);  // which arm's end edge i is, or -1 for a side edge
  for (int i = 0; i < n; ++i) {
    const Vector2d mid = (outline[i] + outline[(i + 1) % n]) / 2;
    for (int k = 0; k < 4; ++k) {
      if (lengths[k] > 0 && (mid - (h + lengths[k]) * Direction(k)).norm() < 1e-9) arm_end[i] = k;
    }
  }
  std::vector<OutlineEdge> edges(n);
  std::vector<std::string> ends;
  world.closed = true;
  for (int i = 0; i < n; ++i) {
    if (arm_end[i] < 0) continue;
    edges[i].built = !rng.Chance(0.25);
    world.closed = world.closed && edges[i].built;
    ends.push_back(JsonString(edges[i].built ? "closed" : "open"));
  }
  struct Side {
    int edge;
    double from, width;
    bool alcove;
  };
  std::vector<Side> sides;
  const int n_sides = rng.Int(0, 3);
  for (int s = 0; s < n_sides; ++s) {
    bool placed = false;
    for (int t = 0; t < 100 && !placed; ++t) {
      const int e = rng.Int(0, n - 1);
      const double length = (outline[(e + 1) % n] - outline[e]).norm();
      const double w = rng.Rounded(0.6, 1.2, 0.01);
      if (arm_end[e] >= 0 || length < w + 2 * kCorridorJambM) continue;
      const double from = rng.Rounded(kCorridorJambM, length - kCorridorJambM - w, 0.01);
      bool clear = true;
      for (const Side& o : sides) {
        clear = clear && (o.edge != e || from > o.from + o.width + kCorridorJambM ||
                          from + w + kCorridorJambM < o.from);
      }
      if (!clear) continue;
      sides.push_back({e, from, w, rng.Chance(0.5)});
      placed = true;
    }
    if (!placed) return std::nullopt;
  }
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) {
    return a.edge < b.edge || (a.edge == b.edge && a.from < b.from);
  });
  for (const Side& s : sides) edges[s.edge].openings.push_back({s.from, s.from + s.width});
  const auto edge_geoms = AddOutlineWalls(world, outline, edges);
  world.interiors.push_back(outline);
  std::vector<std::string> described;
  for (const Side& s : sides) {
    const EdgeFrame edge = EdgeFrame::Of(outline, s.edge);
    std::vector<WorldParameter> fields = {{"edge", JsonNumber(s.edge)},
                                          {"from_m", JsonNumber(s.from)},
                                          {"width_m", JsonNumber(s.width)},
                                          {"behind", JsonString(s.alcove ? "alcove" : "nothing")}};
    if (s.alcove) {
      const double depth = rng.Rounded(1.0, 2.5, 0.01);
      // Its side walls stay kCorridorJambM from the corridor's corners (and never inside the
      // opening).
      const double from = std::max(kCorridorJambM, s.from - rng.Rounded(0.0, 0.8, 0.01));
      const double to =
          std::min(edge.length_m - kCorridorJambM, s.from + s.width + rng.Rounded(0.0, 0.8, 0.01));
      if (!AddAlcove(world, edge, from, to, depth, edge_geoms[s.edge], 0.25)) return std::nullopt;
      fields.push_back({"alcove_depth_m", JsonNumber(depth)});
      fields.push_back({"alcove_width_m", JsonNumber(to - from)});
    } else {
      world.closed = false;
    }
    described.push_back(JsonObject(fields));
  }
  const double rotation = rng.Rounded(0.0, 359.9, 0.1);
  std::vector<double> arm_lengths;
  for (int k = 0; k < 4; ++k) {
    if (lengths[k] > 0) arm_lengths.push_back(lengths[k]);
  }
  world.parameters = {
      {"junction", JsonString(kJunctions[junction])}, {"width_m", JsonNumber(width)},
      {"arm_lengths_m", JsonNumbers(arm_lengths)},    {"ends", JsonArray(ends)},
      {"side_openings", JsonArray(described)},        {"rotation_deg", JsonNumber(rotation)}};
  char text[160];
  std::snprintf(text, sizeof(text), "%s corridor %.2f m wide turned %.1f deg, %zu side opening%s",
                kJunctions[junction], width, rotation, sides.size(), sides.size() == 1 ? "" : "s");
  world.summary = text;
  return rotation;
}

}  // namespace plywood::sim::worldgen
