#pragma once

#include "perception/sonar_map/beam_free_grid.h"
#include "perception/sonar_map/frontier_planner.h"
#include "perception/sonar_map/log_odds_grid.h"
#include "perception/sonar_map/partition_map.h"

namespace plywood::perception {

// Which sides of a reported room the robot has sensed floor beyond: a side is seen past when,
// beyond it and within the room's span along it, there is a patch of floor seen free (a free cell
// in `cells`, or a cell the sonar axes passed at least `min_passes` times in `beam_free`, when
// given) at least `min_length_m` long along the side, every part of it seen free over more than
// `min_depth_m` outwards. A room fitted early on the faces of a box heard from a pocket has such a
// side (the floor past the box seen through a gap); a wall heard from the inside has only stray
// cells beyond it (issue 14, docs/sonar_map/history.md round 58b).
struct RoomSides {
  bool west = false, south = false, east = false, north = false;
  bool Any() const { return west || south || east || north; }
  bool operator==(const RoomSides&) const = default;
};
RoomSides SidesSeenPast(const CellMap& cells, const LogOddsGrid& grid,
                        const BeamFreeGrid* beam_free, int min_passes, const Rect& room,
                        double min_length_m, double min_depth_m);

// `room` with the sides in `open` moved out to the grid's outer edge: where the room ends beyond
// them the robot cannot tell, so the floor there counts as not seen.
Rect OpenSides(const Rect& room, const RoomSides& open, const LogOddsGrid& grid);

}  // namespace plywood::perception
