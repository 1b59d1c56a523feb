#include "sim/world/generator/world_families.h"

#include <stdexcept>

namespace plywood::sim::worldgen {

const std::vector<WorldFamily>& WorldFamilies() {
  static const std::vector<WorldFamily> families = {
      {"room", "empty rectangle, L or T room, 3-10 m, any rotation", 3, &DrawRoomWorld},
      {"doorways", "room with 1-3 openings of 0.3-1.2 m: nothing, a panel or an alcove behind", 3,
       &DrawDoorwaysWorld},
      {"columns", "room with round columns (r 0.03-0.3 m) and tables on 4 thin legs", 3,
       &DrawColumnsWorld},
      {"clutter", "room with 2-8 rotated boxes of 0.1-0.6 m", 3, &DrawClutterWorld},
      {"stubs", "4-5 corners of 60-120 deg, chamfers and short wall stubs", 3, &DrawStubsWorld},
      {"corridor", "straight, L, T or X corridor junction with side openings and alcoves", 3,
       &DrawCorridorWorld},
      {"seed001",
       "about 3.5 x 3 m room with 0-3 boxes: against, near (0.3-1.2 m) or off the "
       "walls, L-shaped pairs",
       3, &DrawSeed001World},
      {"office", "offices on both sides of a corridor, doors, tables, wardrobes, >= 15 x 10 m", 4,
       &DrawOfficeWorld},
  };
  return families;
}

const WorldFamily& FindWorldFamily(const std::string& name) {
  std::string known;
  for (const WorldFamily& f : WorldFamilies()) {
    if (f.name == name) return f;
    known += (known.empty() ? "" : ", ") + f.name;
  }
  throw std::invalid_argument("family: unknown world family '" + name + "' (known: " + known + ")");
}

}  // namespace plywood::sim::worldgen
