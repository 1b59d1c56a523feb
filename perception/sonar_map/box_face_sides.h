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

// The same, with the floor seen past a side only through a gap in it: the patch lies beyond a
// stretch of the side's line at least `min_width_m` long with no occupied cell in `cells` within
// two cells of the line, and the floor seen past it along each line across the side does not end
// on an occupied cell. Box faces the line fit took for a wall leave such gaps beside them; a true
// wall's heard cells run along the side, and where the network painted free cells into one (the
// free cells of 40 of the 49 walls that round 64a opened lie in such gaps) its back is heard
// behind them (issue 14 round 64b).
RoomSides SidesSeenPastThroughGaps(const CellMap& cells, const LogOddsGrid& grid,
                                   const BeamFreeGrid* beam_free, int min_passes, const Rect& room,
                                   double min_width_m, double min_depth_m);

// `room` with the sides in `open` moved out to the grid's outer edge: where the room ends beyond
// them the robot cannot tell, so the floor there counts as not seen.
Rect OpenSides(const Rect& room, const RoomSides& open, const LogOddsGrid& grid);

}  // namespace plywood::perception
