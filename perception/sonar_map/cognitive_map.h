#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "perception/sonar_map/beam_free_grid.h"
#include "perception/sonar_map/log_odds_grid.h"
#include "perception/sonar_map/partition_map.h"

namespace plywood::perception {

// Every constant seed 001 leaves open for turning the occupancy grid into its map.
struct CognitiveMapOptions {
  double eps = 0.3;               // boundary cells: P > 1 - eps
  double snap_distance_m = 0.15;  // d_e: lines closer than this to an earlier aligned line snap
  double fit_sigma_m = 0.05;      // per-point sigma of the chi-square fits (half a 10 cm cell)
  int min_wall_points = 5;        // a room side needs this many boundary points
  int min_obstacle_cells = 6;     // smaller occupied blobs inside the room are noise
  double wall_band_m = 0.15;      // occupied cells this close inside a wall line belong to it
  double min_passage_m = 0.45;    // free-free stretches narrower than the robot go into D
  // A room side with more free space than this beyond it is an obstacle face, not the wall (the
  // faces the axes agree on count from the fitted side, however far free columns moved it out).
  double side_free_overrun_m = 0.3;
  // An obstacle blob grows over every cell not seen free with P below this (<= eps): corner
  // echoes off the junction of an obstacle and a wall make its face look faintly free.
  double obstacle_free_p = 0.3;
  // Obstacle pieces closer than this to each other or to a room side are joined to them: to a
  // side by extending the piece to it; to each other by their extent when that is about their
  // areas plus the gap's (a face split in two), else by filling the gap between their facing
  // sides (CognitiveMap::bridges); diagonal neighbours stay apart. 0.3 m joined true gaps of
  // 0.3-0.45 m that the grid narrowed (a face it places is 0.08 m short to 0.13 m out, 10-90 %)
  // and the scorer counts as free: generated rooms, seed 1, mean e 0.0187 -> 0.0162 with 0.2 m.
  double obstacle_join_m = 0.2;
  // With the axes' free space (the reported map only): a piece within obstacle_join_m of a room
  // side is not extended to it when a cell of the strip's line along that side (within one cell of
  // it, across the piece's span) counts as heard free for the peel (obstacle_peel_free's cells):
  // the sonar heard the space along the wall behind the piece, so there is a gap, and the piece's
  // side near the wall is the network's blur of a face it did not hear head-on. A box flush with
  // the wall has its own back there, never heard free. Issue 14 round 34: generated rooms, p90
  // 0.0786 -> 0.0660 (seed 10), held-out seeds 18 / 19 0.0474 -> 0.0436, 0.0581 -> 0.0545.
  bool obstacle_wall_join_seen_free = true;
  // With obstacle_wall_join_seen_free: a side that evidence kept off the room side is not snapped
  // (snap_distance_m) onto it either; it may still snap to other lines. d_e (0.15 m) is below
  // obstacle_join_m, so the snap joined every piece nearer than d_e to the wall whatever the strip
  // held. Issue 14 round 35: generated rooms, p90 0.0660 -> 0.0620 (seed 10), 0.0676 -> 0.0599
  // (seed 5); held-out seeds 20 / 21: 11 / 13 runs down, none up.
  bool obstacle_wall_snap_seen_free = true;
  // The rectangles span the blob's occupied cells (the faces heard) only, not the unknown cells
  // the blob grew over: a box's unheard inside lies between its faces anyway, while the unseen
  // gap between a box and a wall made the box reach the wall.
  bool obstacle_from_faces = true;
  // Obstacle sides: the blob's extent (false) or a chi-square fit of its extreme cells (true).
  bool fit_obstacle_sides = false;
  // The extent spans only the outermost rows (columns) the blob fills to at least this fraction of
  // its fullest row (column): corner echoes where a box meets a wall paint occupied wedges that
  // taper along the wall, while a box, whose inside the sonar never sees free, fills every row.
  // 0 keeps the whole blob.
  double obstacle_min_fill = 0.3;
  // (The reported map, with a BeamFreeGrid.) An end the trim above would drop is kept when its
  // occupied cells hold at least beam_free_min_passes echo points of the grid-aligned axes: a face
  // heard head-on there, i.e. a second box the network's blur joined to a taller neighbour (whose
  // fullest column made the box's own columns look thin), not the corner echoes' wedge. Issue 14
  // round 35: generated rooms, mean 0.0303 -> 0.0296 (seed 19), held-out seed 22 p90 0.0734 ->
  // 0.0639.
  bool obstacle_trim_keeps_heard_ends = true;
  // A blob is cut in two (up to three times, so into at most 8 rectangles) where the two pieces'
  // extents cover at least this fraction less area than the blob's: an L-shaped pair of boxes, or a
  // box with the unseen strip along a wall beside it, is no rectangle. 1 never cuts.
  double obstacle_split_saving = 0.25;
  // Long-range free space (BeamFreeGrid, when BuildCognitiveMap is given one): a cell that at least
  // this many beam axes passed through counts as seen free for placing the room's sides (the
  // network sees +-0.7 m only, so a wall beyond boxes the robot cannot pass was never seen), and is
  // no part of an obstacle (the network paints occupied cells into gaps 0.3-0.6 m wide between a
  // box and a wall, which then joined the box to the wall). The faces those axes heard head-on
  // (BeamFreeGrid::face_echoes) also place the sides: a room side at the median of at least
  // min_wall_points of them within wall_band_m, an obstacle side at the median of at least this
  // many (and then not snapped). 0: not used.
  int beam_free_min_passes = 2;
  // With the axes' free space (the reported map only): an obstacle piece's rectangle gives up an
  // outermost row or column holding more cells the axes passed (>= beam_free_min_passes) than
  // cells of the piece, and again, so a rectangle does not span space the axes heard free beside
  // its faces (an L's notch the network painted); the cells given up form pieces of their own.
  bool obstacle_peel_free = true;
  // The peel counts the network's free cells (P < eps) too where no occupied cell (P > 1 - eps)
  // lies within this distance: the network paints cells free inside a box's face, beside its
  // echoes; like the axes (BeamFreeOptions::stop_short_m) a free cell must lie the range noise
  // from any echo. It lets the peel free what the network saw and no axis passed. 0: axes only.
  double obstacle_peel_net_free_clearance_m = 0.05;
  // (The reported map, with the axes' free space and obstacle_from_faces.) A piece (after the
  // cut into rectangles) whose faces lie more than obstacle_join_m apart, joined only by cells
  // never heard free (the unknown the blob grows over), is cut into one obstacle per group of
  // faces, each cut into rectangles again, where a face heard in one group faces the other: at
  // least beam_free_min_passes echoes of the axes in one group's cells came from a transducer on
  // the side where the other group wholly lies (ClustersHeardApart). The blob grows over every
  // cell not seen free, so two boxes whose gap the robot never saw became one blob, and when no
  // cut saved obstacle_split_saving a rectangle spanned both and the gap (issue 14 round 41b,
  // class C). A box's faces all lie behind any face of it heard head-on, as seen from where it
  // was heard, so one box seen from two sides (opposite faces heard from outside, its inside
  // never) stays one: round 41b's cut without that cue cut such a box into its faces (classical
  // model, generator seed 44 world 9 s2 0.031 -> 0.103; issue 14 round 42b). Closer faces stay
  // one piece, as obstacle_join_m would join them anyway.
  bool obstacle_cut_unheard_gaps = true;
  // (With obstacle_cut_unheard_gaps, where its groups by obstacle_join_m left a piece whole.) The
  // piece's cells grouped again by the cells at least this many readings called occupied
  // (LogOddsGrid::OccupiedVotes), groups more than half obstacle_join_m apart, the others going
  // with the nearest group, and cut where a face heard in one group faces another, as above
  // (ClustersOfWellPaintedCellsHeardApart).
  // The network paints its +-0.7 m window from every reading, so the unseen gap between two boxes
  // 0.3-0.5 m apart gets occupied cells from a few far readings (median 3 in issue 14 round 43b's
  // traced runs; a box's inside 33): that blur joined the boxes' faces closer than obstacle_join_m
  // and a rectangle spanned both (class C's painted gap). 0: off. 6 (round 43b's value) is the
  // default since its held-out sweeps (stop 46: 2,800 runs of fresh generator seeds 51-53 with
  // both cell models, seeds 48-50, the layouts; 3 runs down, none up).
  int obstacle_cut_min_votes = 6;
  // (The reported map, with the axes' free space.) A room side beyond which floor was seen free
  // through a gap in the side (SidesSeenPastThroughGaps: no heard cell within two cells of the
  // side's line over at least this length along it, the floor seen past more than a cell deep and
  // not ending on a heard cell) is taken for a box's face nearer than the wall and opened to the
  // grid's edge (OpenSides): the floor behind it is mapped free but for the obstacles heard there.
  // 0.4 m is the body's width (2 robot_radius_m). Round 64a opened a side on any floor seen past
  // it; 49 of its 50 sides on the held-out sweeps were true walls the network had painted free
  // cells into; the gap rule leaves 43 of them, and on the twelve held-out sweeps it moves one run
  // of 1,800 (g69 w22 s2 0.2985 -> 0.1277), none up, and fresh seed 87 and the classical model on
  // seeds 69 and 74 hold too: the default since round 64b. 0: off.
  double open_sides_seen_past_m = 0.4;
  // @throws std::invalid_argument naming the field.
  void Validate() const;
};

// The abstraction of one grid: the room's four boundary lines (axis-parallel, each from a
// chi-square fit of the boundary cells nearest the robot), the obstacles' rectangles (each side a
// fit of its boundary cells, snapped within d_e to earlier lines), the partitions, D and the graph.
struct CognitiveMap {
  Rect room;
  std::vector<Rect> obstacles;
  // Gaps narrower than obstacle_join_m between two obstacles facing each other, filled: the robot
  // cannot pass them. Obstacle partitions like the obstacles, but no obstacle of their own.
  std::vector<Rect> bridges;
  std::vector<Eigen::Vector2d> corners;
  PartitionMap partitions;
  std::vector<Adjacency> adjacency;
  NegativeExperience negative;
  TopologicalGraph graph;
};

// The cells of `cells` inside the box spanned by the outermost rows and columns holding at least
// min_fill times as many of them as the fullest row (column); cells between such rows stay, however
// few. Empty input gives empty output.
std::vector<Eigen::Vector2i> TrimThinEnds(const std::vector<Eigen::Vector2i>& cells,
                                          double min_fill);

// The cells of a blob as rectangular pieces: cut at the row or column that most shrinks the
// summed extents of the two sides, while that saves at least `saving` of the extent's area (and
// anything at all), at most `max_depth` times deep. Every cell is in exactly one piece; one piece
// when no cut saves enough.
std::vector<std::vector<Eigen::Vector2i>> SplitIntoRectangles(
    const std::vector<Eigen::Vector2i>& cells, double saving, int max_depth);

// The cells of `cells` inside the box left when its outermost rows and columns holding more
// cells for which is_free(cell) holds (any cell of the box, in `cells` or not) than cells of
// `cells` are dropped, one at a time (the side with the largest excess first), while any does;
// `rest` receives the cells dropped. Empty input gives empty output.
std::vector<Eigen::Vector2i> PeelFreeEdges(const std::vector<Eigen::Vector2i>& cells,
                                           const std::function<bool(int, int)>& is_free,
                                           std::vector<Eigen::Vector2i>& rest);

// `inside`: a point known to be free inside the room (the start pose). Sides without enough
// boundary points fall back to the outermost cell the grid has seen free. `beam_free` (same cells
// as `grid`, may be null): the long-range free space of the sonar axes.
CognitiveMap BuildCognitiveMap(const LogOddsGrid& grid, const Eigen::Vector2d& inside,
                               const CognitiveMapOptions& options,
                               const BeamFreeGrid* beam_free = nullptr);

}  // namespace plywood::perception
