// Family `office`: an office floor of 15-22 x 10-14 m: a corridor 1.4-2 m wide along x, 2-4 rooms
// on each side with a 0.8-1 m door onto it (and sometimes one into the next room), tables on
// legs, wardrobes and cabinets against the walls, 0-2 columns in the corridor. Axis-aligned like
// worlds/office.xml; doors stay clear of furniture.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sim/world/generator/placement.h"
#include "sim/world/generator/wall_builder.h"
#include "sim/world/generator/world_families.h"

namespace plywood::sim::worldgen {

using Eigen::Vector2d;

namespace {

constexpr double kT = kWallThicknessM;
constexpr double kOfficeJambM = 0.3;
constexpr double kOfficeGapM = 0.3;    // between furniture, and from furniture to walls (or 0)
constexpr double kDoorKeepOutM = 1.0;  // furniture-free depth on both sides of a door

struct Room {
  Vector2d lo, hi;  // floor inside the walls
  bool north = true;
};

// A plywood wall with its face on y = `face_y`, on the side `sign`
// (+1: the box lies at y >= face_y), from x0 to x1, with door openings [from, to] in x.
void AddWallAlongX(GeneratedWorld& world, double face_y, int sign, double x0, double x1,
                   const std::vector<std::pair<double, double>>& doors) {
  double from = x0;
  auto piece = [&](double a, double b) {
    if (b - a > 1e-9) world.AddWallBox({(a + b) / 2, face_y + sign * kT / 2}, (b - a) / 2, 0.0);
  };
  for (const auto& [d0, d1] : doors) {
    piece(from, d0);
    from = d1;
  }
  piece(from, x1);
}

// A partition centred on x from y0 to y1, with an optional door [from, to] in y.
void AddPartition(GeneratedWorld& world, double x, double y0, double y1,
                  const std::optional<std::pair<double, double>>& door) {
  auto piece = [&](double a, double b) {
    if (b - a > 1e-9) world.AddWallBox({x, (a + b) / 2}, (b - a) / 2, 90.0);
  };
  if (door) {
    piece(y0, door->first);
    piece(door->second, y1);
  } else {
    piece(y0, y1);
  }
}

// Cut positions splitting [x0, x1] into n rooms of roughly equal width (each 0.75-1.25 of the
// mean before normalising), rounded to 5 cm.
std::vector<double> Cuts(WorldRng& rng, double x0, double x1, int n) {
  std::vector<double> f;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    f.push_back(rng.Uniform(0.75, 1.25));
    sum += f.back();
  }
  std::vector<double> cuts = {x0};
  double acc = 0;
  for (int i = 0; i + 1 < n; ++i) {
    acc += f[i];
    cuts.push_back(std::round((x0 + (x1 - x0) * acc / sum) * 20) / 20);
  }
  cuts.push_back(x1);
  return cuts;
}

bool InsideRoom(const Room& room, const Footprint& f) {
  for (const Vector2d& c : f.corners) {
    if (c.x() < room.lo.x() - 1e-9 || c.x() > room.hi.x() + 1e-9 || c.y() < room.lo.y() - 1e-9 ||
        c.y() > room.hi.y() + 1e-9) {
      return false;
    }
  }
  return true;
}

// A footprint of `half` (x along the wall) standing against one of the room's walls other than
// the corridor's, or anywhere when `against_wall` is false; axis-aligned.
Footprint DrawSpot(WorldRng& rng, const Room& room, const Vector2d& half, bool against_wall,
                   Vector2d* centre, double* yaw_deg) {
  const int side = against_wall ? rng.Int(0, 2) : -1;  // 0 far wall, 1 west, 2 east
  Vector2d h = half;
  *yaw_deg = 0.0;
  if (side == 1 || side == 2 || (side < 0 && rng.Chance(0.5))) {
    h = {half.y(), half.x()};
    *yaw_deg = 90.0;
  }
  Vector2d c(rng.Rounded(room.lo.x() + h.x(), room.hi.x() - h.x(), 0.01),
             rng.Rounded(room.lo.y() + h.y(), room.hi.y() - h.y(), 0.01));
  if (side == 0) c.y() = room.north ? room.hi.y() - h.y() : room.lo.y() + h.y();
  if (side == 1) c.x() = room.lo.x() + h.x();
  if (side == 2) c.x() = room.hi.x() - h.x();
  *centre = c;
  // The footprint in the world: `half` turned by yaw is the axis-aligned `h`.
  return Footprint::Box(c, h, 0.0);
}

}  // namespace

std::optional<double> DrawOfficeWorld(WorldRng& rng, GeneratedWorld& world) {
  const double w = rng.Rounded(15.0, 22.0, 0.1);
  const double d = rng.Rounded(10.0, 14.0, 0.1);
  const double cw = rng.Rounded(1.4, 2.0, 0.05);
  const double yc = rng.Rounded(-d / 2 + 3.5 + cw / 2, d / 2 - 3.5 - cw / 2, 0.05);
  const double y_n = yc + cw / 2, y_s = yc - cw / 2;
  const std::vector<Vector2d> outline = {
      {-w / 2, -d / 2}, {w / 2, -d / 2}, {w / 2, d / 2}, {-w / 2, d / 2}};
  AddOutlineWalls(world, outline, std::vector<OutlineEdge>(4));
  world.interiors.push_back(outline);
  world.closed = true;

  const int max_rooms = static_cast<int>(w / 4.5);
  std::vector<Room> rooms;
  std::vector<Footprint> keep_out;
  std::vector<std::string> room_params;
  for (const bool north : {true, false}) {
    const int n = rng.Int(2, max_rooms);
    const std::vector<double> cuts = Cuts(rng, -w / 2, w / 2, n);
    const double y0 = north ? y_n + kT : -d / 2, y1 = north ? d / 2 : y_s - kT;
    std::vector<std::pair<double, double>> doors;
    for (int i = 0; i < n; ++i) {
      Room room;
      room.north = north;
      room.lo = {cuts[i] + (i > 0 ? kT / 2 : 0.0), y0};
      room.hi = {cuts[i + 1] - (i + 1 < n ? kT / 2 : 0.0), y1};
      const double door_w = rng.Rounded(0.8, 1.0, 0.01);
      const double door_x =
          rng.Rounded(room.lo.x() + kOfficeJambM, room.hi.x() - kOfficeJambM - door_w, 0.01);
      doors.push_back({door_x, door_x + door_w});
      const double face = north ? y_n : y_s;
      keep_out.push_back(
          Footprint::Box({door_x + door_w / 2, face}, {door_w / 2 + 0.2, kDoorKeepOutM}, 0.0));
      room_params.push_back(JsonObject({{"side", JsonString(north ? "north" : "south")},
                                        {"x_m", JsonNumbers({room.lo.x(), room.hi.x()})},
                                        {"door_m", JsonNumbers({door_x, door_w})}}));
      rooms.push_back(room);
    }
    if (north) {
      AddWallAlongX(world, y_n, +1, -w / 2, w / 2, doors);
    } else {
      AddWallAlongX(world, y_s, -1, -w / 2, w / 2, doors);
    }
    for (int i = 1; i < n; ++i) {
      std::optional<std::pair<double, double>> door;
      if (rng.Chance(0.3)) {
        const double door_w = rng.Rounded(0.8, 1.0, 0.01);
        const double from = rng.Rounded(y0 + kOfficeJambM, y1 - kOfficeJambM - door_w, 0.01);
        door = std::pair{from, from + door_w};
        keep_out.push_back(
            Footprint::Box({cuts[i], from + door_w / 2}, {kDoorKeepOutM, door_w / 2 + 0.2}, 0.0));
      }
      AddPartition(world, cuts[i], y0, y1, door);
    }
  }
  auto clear_of_doors = [&](const Footprint& f) {
    for (const Footprint& k : keep_out) {
      if (Overlap(f, k)) return false;
    }
    return true;
  };

  // Columns on the corridor's centre line.
  const int n_columns = rng.Int(0, 2);
  std::vector<double> column_radii;
  for (int i = 0; i < n_columns; ++i) {
    const double r = rng.Rounded(0.1, 0.2, 0.01);
    bool placed = false;
    for (int t = 0; t < 100 && !placed; ++t) {
      const Footprint f = Footprint::Disc({rng.Rounded(-w / 2 + 1, w / 2 - 1, 0.01), yc}, r);
      bool apart = true;  // columns at least 2 m apart
      for (const WorldGeom& g : world.geoms) {
        apart = apart && (g.name.rfind("column_", 0) != 0 || (g.centre - f.centre).norm() >= 2.0);
      }
      if (!apart || !clear_of_doors(f) || !Fits(world, f, 0.4)) continue;
      world.AddCylinder("column", "obstacle", f.centre, r, 1.0);
      column_radii.push_back(r);
      placed = true;
    }
    if (!placed) return std::nullopt;
  }

  // Furniture, room by room.
  int tables = 0, wardrobes = 0, cabinets = 0;
  for (const Room& room : rooms) {
    struct Item {
      std::string kind;
      Vector2d half;
      double height;
      bool against_wall;
    };
    std::vector<Item> items;
    if (rng.Chance(0.6))
      items.push_back({"wardrobe", {rng.Rounded(0.4, 0.6, 0.01), 0.3}, 2.0, true});
    if (rng.Chance(0.3))
      items.push_back({"cabinet", {rng.Rounded(0.4, 0.6, 0.01), 0.25}, 0.8, true});
    const int n_tables = rng.Int(0, 2);
    for (int i = 0; i < n_tables; ++i) {
      items.push_back({"table",
                       {rng.Rounded(0.6, 0.9, 0.01), rng.Rounded(0.35, 0.45, 0.01)},
                       0.75,
                       rng.Chance(0.5)});
    }
    for (const Item& item : items) {
      bool placed = false;
      for (int t = 0; t < 100 && !placed; ++t) {
        Vector2d centre;
        double yaw;
        const Footprint f = DrawSpot(rng, room, item.half, item.against_wall, &centre, &yaw);
        if (!InsideRoom(room, f) || !clear_of_doors(f) ||
            !FitsAgainstWalls(world, f, kOfficeGapM)) {
          continue;
        }
        if (item.kind == "table") {
          world.AddTable(centre, item.half, yaw, item.height, 0.025, 0.035);
          ++tables;
        } else {
          world.AddBox(item.kind, "wardrobe", centre, {item.half.x(), item.half.y()}, yaw,
                       item.height);
          ++(item.kind == "wardrobe" ? wardrobes : cabinets);
        }
        placed = true;
      }
      // A room too full for one more piece simply goes without it.
    }
  }
  world.parameters = {
      {"width_m", JsonNumber(w)},           {"depth_m", JsonNumber(d)},
      {"corridor_width_m", JsonNumber(cw)}, {"corridor_centre_y_m", JsonNumber(yc)},
      {"rooms", JsonArray(room_params)},    {"column_radii_m", JsonNumbers(column_radii)},
      {"tables", JsonNumber(tables)},       {"wardrobes", JsonNumber(wardrobes)},
      {"cabinets", JsonNumber(cabinets)}};
  char text[200];
  std::snprintf(text, sizeof(text),
                "%.1f x %.1f m office floor, %zu rooms off a %.2f m corridor, %d tables, %d "
                "wardrobes, %d cabinets, %d columns",
                w, d, rooms.size(), cw, tables, wardrobes, cabinets, n_columns);
  world.summary = text;
  return 0.0;
}

}  // namespace plywood::sim::worldgen
