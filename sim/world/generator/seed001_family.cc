// Family `seed001`: rooms like seed 001's (about 3.5 x 3 m, axis-aligned) with 0-3 obstacles
// 0.6 m tall: a box against a wall, a box in a corner, a box 0.3-1.2 m from a wall, a free box or
// an L-shaped pair of boxes. Every gap between an obstacle and a wall or another obstacle is 0
// (standing against it) or at least 0.3 m, so no slit narrower than a robot opens.
#include <cstdio>

#include "sim/world/generator/placement.h"
#include "sim/world/generator/wall_builder.h"
#include "sim/world/generator/world_families.h"

namespace plywood::sim::worldgen {

using Eigen::Vector2d;

namespace {

constexpr double kHeightM = 0.6;  // above the Magellan Pro's sonars, as in worlds/seed001_room_*
constexpr double kMinGapM = 0.3, kMaxGapM = 1.2;
const char* const kKinds[] = {"wall", "corner", "gap", "free", "L"};

struct Rect {  // axis-aligned, by corners
  Vector2d lo, hi;
  Vector2d Centre() const { return (lo + hi) / 2; }
  Vector2d Half() const { return (hi - lo) / 2; }
};

// Where a bounding box of `size` goes in the w x d room for a placement kind.
struct Placement {
  Rect box;
  double gap_m = 0.0;  // "gap": distance to the chosen wall
};

Placement Place(WorldRng& rng, const std::string& kind, const Vector2d& size, double w, double d) {
  const Vector2d lo_room(-w / 2, -d / 2), hi_room(w / 2, d / 2);
  Placement p;
  Vector2d lo(rng.Rounded(lo_room.x(), hi_room.x() - size.x(), 0.01),
              rng.Rounded(lo_room.y(), hi_room.y() - size.y(), 0.01));
  if (kind == "wall" || kind == "gap") {
    const int side = rng.Int(0, 3);  // south, east, north, west
    const double gap = kind == "gap" ? rng.Rounded(kMinGapM, kMaxGapM, 0.01) : 0.0;
    if (side == 0) lo.y() = lo_room.y() + gap;
    if (side == 1) lo.x() = hi_room.x() - gap - size.x();
    if (side == 2) lo.y() = hi_room.y() - gap - size.y();
    if (side == 3) lo.x() = lo_room.x() + gap;
    p.gap_m = gap;
  } else if (kind == "corner") {
    const int corner = rng.Int(0, 3);
    lo.x() = corner == 0 || corner == 3 ? lo_room.x() : hi_room.x() - size.x();
    lo.y() = corner < 2 ? lo_room.y() : hi_room.y() - size.y();
  }
  p.box = {lo, lo + size};
  return p;
}

Footprint BoxFootprint(const Rect& r) { return Footprint::Box(r.Centre(), r.Half(), 0.0); }

}  // namespace

std::optional<double> DrawSeed001World(WorldRng& rng, GeneratedWorld& world) {
  const double w = rng.Rounded(3.2, 3.8, 0.01);
  const double d = rng.Rounded(2.8, 3.2, 0.01);
  const std::vector<Vector2d> outline = {
      {-w / 2, -d / 2}, {w / 2, -d / 2}, {w / 2, d / 2}, {-w / 2, d / 2}};
  AddOutlineWalls(world, outline, std::vector<OutlineEdge>(4));
  world.interiors.push_back(outline);
  world.closed = true;

  const int n = rng.Int(0, 3);
  std::vector<std::string> obstacles, kinds;
  for (int i = 0; i < n; ++i) {
    const std::string kind = kKinds[rng.Int(0, 4)];
    std::vector<Rect> parts;  // in the bounding box's frame, lo at the origin
    Vector2d size;
    std::vector<WorldParameter> fields = {{"kind", JsonString(kind)}};
    std::string placement = kind;
    if (kind == "L") {
      // Arm A along x, arm B up from A's west end; turned by a multiple of 90 deg.
      const double la = rng.Rounded(0.6, 1.0, 0.01), ta = rng.Rounded(0.25, 0.4, 0.01);
      const double lb = rng.Rounded(0.4, 0.8, 0.01), tb = rng.Rounded(0.25, 0.4, 0.01);
      const int turn = rng.Int(0, 3);
      std::vector<Rect> l = {{{0, 0}, {la, ta}}, {{0, ta}, {tb, ta + lb}}};
      size = {la, ta + lb};
      for (int q = 0; q < turn; ++q) {  // a quarter turn inside the bounding box
        for (Rect& r : l) r = {{size.y() - r.hi.y(), r.lo.x()}, {size.y() - r.lo.y(), r.hi.x()}};
        size = {size.y(), size.x()};
      }
      parts = l;
      placement = kKinds[rng.Int(0, 3)];
      fields.push_back({"arms_m", JsonNumbers({la, ta, lb, tb})});
      fields.push_back({"turn_deg", JsonNumber(90.0 * turn)});
      fields.push_back({"placement", JsonString(placement)});
    } else {
      size = {rng.Rounded(0.3, 0.9, 0.01), rng.Rounded(0.3, 0.9, 0.01)};
      parts = {{{0, 0}, size}};
      fields.push_back({"size_m", JsonNumbers({size.x(), size.y()})});
    }
    bool placed = false;
    for (int t = 0; t < 200 && !placed; ++t) {
      const Placement p = Place(rng, placement, size, w, d);
      bool fits = true;
      for (const Rect& r : parts) {
        fits = fits &&
               FitsAgainstWalls(world, BoxFootprint({p.box.lo + r.lo, p.box.lo + r.hi}), kMinGapM);
      }
      if (!fits) continue;
      for (const Rect& r : parts) {
        const Rect moved{p.box.lo + r.lo, p.box.lo + r.hi};
        world.AddBox("obstacle", "obstacle", moved.Centre(), moved.Half(), 0.0, kHeightM);
      }
      fields.push_back({"centre_m", JsonNumbers({p.box.Centre().x(), p.box.Centre().y()})});
      if (placement == "gap") fields.push_back({"gap_m", JsonNumber(p.gap_m)});
      placed = true;
    }
    if (!placed) return std::nullopt;
    obstacles.push_back(JsonObject(fields));
    kinds.push_back(kind == "L" ? "L-shaped pair (" + placement + ")" : "box (" + kind + ")");
  }
  world.parameters = {
      {"width_m", JsonNumber(w)}, {"depth_m", JsonNumber(d)}, {"obstacles", JsonArray(obstacles)}};
  char text[200];
  std::snprintf(text, sizeof(text), "%.2f x %.2f m room, %d obstacle%s", w, d, n,
                n == 1 ? "" : "s");
  world.summary = text;
  for (size_t k = 0; k < kinds.size(); ++k) world.summary += (k ? ", " : ": ") + kinds[k];
  return 0.0;
}

}  // namespace plywood::sim::worldgen
