#pragma once

#include <Eigen/Core>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "perception/sonar_map/beam_free_grid.h"
#include "perception/sonar_map/cognitive_map.h"
#include "perception/sonar_map/exploration_event.h"
#include "perception/sonar_map/frontier_planner.h"
#include "perception/sonar_map/log_odds_grid.h"
#include "perception/sonar_map/obstacle_circuit.h"
#include "perception/sonar_map/sonar_cell_model.h"
#include "perception/sonar_map/sonar_net.h"
#include "robot/control/controller.h"
#include "robot/control/wall_following_controller.h"
#include "robot/drive/diff_drive_spec.h"

namespace plywood::perception {

// Every constant of seed 001's exploration loop the paper leaves open (docs/sonar_map.md).
struct SonarExplorerOptions {
  std::string sonar_model = "net";  // net | classical
  // Weights of the sonar network (SonarNet file), relative to the data root unless absolute.
  std::string weights_file = "models/sonar_net_v1.txt";
  double grid_half_extent_m = 4.0;  // the global grid spans start +- this
  double grid_resolution_m = 0.05;
  double p_min = 0.02;  // clamp of each reading in the product formula
  double log_odds_limit = 12.0;
  // A cell whose nearest transducer heard nothing gets no update (EchoGatedModel).
  bool misses_say_nothing = true;
  CognitiveMapOptions map;
  // The sonar axes' long-range free space beside the grid (map.beam_free_min_passes uses it).
  BeamFreeOptions beam_free;
  // Obstacle (and wall) perimeter following first: one full turn of the boundary.
  double wall_distance_m = 0.5;     // 0.45 grazed obstacle corners (layout 3)
  double perimeter_turn_rad = 6.0;  // heading change that closes the circuit (2 pi minus slack)
  double perimeter_max_s = 150.0;
  // The follower turns on the spot until the lane ahead is clear by perimeter_front_clearance_m +
  // wall_distance_m; in a cramped part of a small room no heading is, and it turned for the rest
  // of perimeter_max_s (generated rooms: up to 145 s, ~10,000 deg in a run). Once the robot has
  // turned this much without leaving a circle of robot_radius_m, the perimeter ends there and the
  // planner takes over. Two turns: the follower's own turns ended by 3.7 pi in most runs, and
  // ending them at 3 pi changed runs that would have gone on (docs/sonar_map/history.md, round 20).
  double perimeter_stuck_turn_rad = 4.0 * std::numbers::pi;
  // A point a bump panel touched during the perimeter lies where the sonar does not hear (a
  // corner inside its blanking range or met at a grazing angle): while it is in the corridor the
  // body sweeps ahead the robot turns on the spot away from it, as for a front echo, instead of
  // driving into it again after backing off (generated rooms: up to 31 contacts on one corner).
  bool perimeter_avoids_contacts = true;
  // The follower turns on the spot at an inner corner when the wall ahead is this close. With 0.8 m
  // the robot stays about 0.8 m off the walls of a 3 m room; 0.55-0.7 m were tried on unseen rooms
  // (docs/sonar_map.md) and were no better, as the follower then cuts its turns short.
  double perimeter_front_clearance_m = 0.8;
  // Then the seed's utility loop over the partitions.
  double speed_m_s = 0.2;
  double max_wheel_accel_rad_s2 = 5.0;  // limit on the commanded wheel speeds' rate of change
  // A pressed bump panel (panel i centred at 360 i / n deg, as on the Magellan Pro): back away
  // from it for this long at this speed (from a side panel against the motion that met it).
  double bump_back_off_s = 1.5;
  double bump_back_off_speed_m_s = 0.1;
  // A newly pressed panel sets the commanded wheel speeds to zero at once (the acceleration
  // limit applies again from there).
  bool bump_stops_wheels = true;
  // A contact on the opposite half of the body from the one the robot is backing off (while the
  // back-off runs, or within bump_back_off_s after) means the axis is wedged between two obstacles,
  // e.g. a gap between two box corners met on the diagonal: backing off from the second drove it
  // into the first again, for the whole run (generated world 32 of seed 30: 112 contacts). The
  // body is round, so the robot turns on the spot until its axis lies along the gap
  // (perpendicular to the line between the two contact points, facing the side of that line it
  // stands on) and replans. Off: it backs off from the second contact as from any other.
  bool bump_wedge_turns = true;
  double turn_rate_rad_s = 0.8;
  double replan_period_s = 2.0;
  double visit_decay = 0.95;         // lambda: c(p) <- lambda c(p) at every replan
  double unvisited_utility = 100.0;  // K: U(p) of a partition never visited
  double place_size_m = 0.9;         // free partitions are visited as places no larger than this
  double perimeter_min_m = 5.0;      // and at least this far along the boundary
  double visit_radius_m = 0.4;       // being this close to a partition's target counts as a visit
  double clearance_m = 0.4;          // targets keep this far from room walls and obstacles
  double robot_radius_m = 0.2;       // the Magellan Pro's
  // Every path keeps its centre this far from occupied cells and fitted obstacles: the seed's x/y
  // moves when they do, otherwise the shortest way over the grid cells that do.
  double path_clearance_m = 0.45;
  // When nothing is reachable that way, paths may pass this close instead: a passage between two
  // obstacles (or an obstacle and a wall) narrower than 2 path_clearance_m but wide enough for the
  // robot is driven through rather than left unexplored. Between robot_radius_m + front_margin_m
  // and path_clearance_m. 0.3 left the body 2 cm from a face whose outer cells went unheard (the
  // sonar misses a face's outer 5-10 cm at grazing angles): layout 3 touched a box at seeds 3, 9,
  // 18 (docs/sonar_map.md).
  double narrow_clearance_m = 0.35;
  // The last resort before "map_complete": a frontier reached by no path at narrow_clearance_m
  // is approached over free cells this far from the cells heard, i.e. through a gap between heard
  // faces 2 x this wide (0.6 m: the robot is 0.41 m wide). Without it an unknown region behind a
  // gap wider than the robot but heard narrower than 2 narrow_clearance_m was never entered and
  // the map guessed it (generated rooms: e up to 0.45-0.57; docs/sonar_map/history.md rounds
  // 23-24). 0.28 let a layout run touch a box once, 0.30 touches nothing in the layouts x seeds
  // 1-20. 0 = off; otherwise between robot_radius_m + front_margin_m (the front check's corridor)
  // and narrow_clearance_m.
  double squeeze_clearance_m = 0.30;
  // A point a bump panel touched keeps every path's centre min(this, the tier's clearance) away,
  // not the tier's clearance: it is exact to the body (the panel's arc), whereas a heard cell's
  // face may lie anywhere in the cell and the beam. With the tier's clearance, a contact at a box
  // corner the sonar never heard closed a 0.61 m gap the robot fits for good (generated world 46
  // of seed 22; docs/sonar_map/history.md round 37a). 0 = a contact blocks like a heard cell;
  // otherwise more than robot_radius_m (0.25: the front check's corridor).
  double contact_clearance_m = 0.25;
  double stop_range_m = 0.3;  // a front echo closer than this aborts the move (into D)
  // Half-width of that corridor beyond the body. It is narrower than path_clearance_m, so that a
  // planned path is not blocked by the cells that shaped it.
  double front_margin_m = 0.05;
  double waypoint_tolerance_m = 0.08;
  double explore_max_s = 200.0;  // then the run is over even if partitions remain unvisited
  // Once every place was visited, unknown frontiers (frontier_planner.h) are visited too.
  int frontier_min_cells = 3;          // smaller 8-connected frontier clusters are noise
  double frontier_view_m = 0.5;        // a frontier cell the robot came this close to is done
  double frontier_wall_band_m = 0.15;  // unknown cells this close to occupied ones are wall edge
  // Obstacle circuits (the seed's step 5): every obstacle the map fits is gone round once, before
  // places and frontiers, by driving to the corners of its rectangle grown by wall_distance_m
  // (obstacle on the left). Each corner is approached over free cells that keep
  // narrow_clearance_m from what was heard, as far as they reach: a corner behind a gap narrower
  // than the robot's passage is given up there (the gap stays obstacle), one in unseen space is
  // approached as the sonar opens the way. Off: no circuits.
  bool circle_obstacles = true;
  double circuit_reach_m = 0.15;  // a circuit corner this close is reached
  // Whether circuit moves may keep only narrow_clearance_m where path_clearance_m gets no nearer.
  bool circuit_narrow = true;
  double circuit_max_s = 60.0;  // one obstacle's circuit is given up after this long
  // An obstacle that overlaps one already gone round, or comes closer to it than this, is that
  // one (the map is refitted at every replan).
  double circuit_same_m = 0.3;
  // A target whose move a front echo, a heard cell or a bump stopped is never tried again, so a
  // few blocked legs from one spot can give up every frontier goal behind a gap and end the run
  // "map_complete" with most of the room never seen (generated world 38 of seed 47: two legs
  // stopped at 38-39 s by a box face beyond their ends, 59 % of the reported room unknown, e 0.60;
  // docs/sonar_map/history.md, round 42a). When the end test finds nothing left while more than
  // this share of the reported room's cells is unknown, the given-up targets are tried once more
  // (once per run) if a frontier goal among them can be reached. In (0, 1]; 1 = off (no share
  // exceeds it).
  double complete_unknown_share_max = 0.5;
  // Whether the end test judges the reported room's sides before it ends a run (issue 14,
  // docs/sonar_map/history.md round 58b): a run that ends early fits sides on the faces of boxes
  // heard from a pocket. A side the robot has seen floor past (a patch of seen-free cells beyond
  // it, the body's width along it and deep, SidesSeenPast) is opened to the grid's edge before the
  // unknown share is measured, and the circuit corners skipped after blocked moves count as given
  // up, so the retry drives to them again. Off: round 42a's test on the reported room as fitted.
  bool complete_room_check = false;
  // Whether the frontier search gets a last tier (issue 14 round 66a): when no circuit corner, no
  // place and no frontier is left that the robot can reach, and the run would end
  // "map_complete", the frontiers are sought once more on the cells with every occupied cell that
  // the grid-aligned sonar axes passed through at least map.beam_free_min_passes times taken for
  // free (the reported map drops those from its obstacles already: the network keeps cells an
  // oblique transducer heard, whose echo may have come from anywhere in its cone). A frontier
  // found so is followed with those cells free for the planner and the map check too, until that
  // move ends (arrived, given up or bumped); its replans seek only such frontiers, so the goal
  // does not flip between the two rules. A run that never reaches that point is the same as
  // without the option. Off: the run ends there.
  bool last_frontier_through_axis_free = false;
  // Whether the frontier search gets a last tier at the body's own clearance (issue 14 round
  // 66c): when nothing is left that the robot can reach at path_clearance_m, narrow_clearance_m
  // or squeeze_clearance_m (nor through last_frontier_through_axis_free's tier, when that is on
  // too), and the run would end "map_complete", the frontiers are sought once more over free cells
  // robot_radius_m + front_margin_m from the cells heard (the front check's corridor: the closest
  // a move may come to what it drives past without stopping), i.e. through a gap between heard
  // faces the body's width plus two margins wide. A frontier found so is driven to at
  // bump_back_off_speed_m_s, the speed the robot backs off a touch at, and its replans seek only
  // such frontiers until that move ends (arrived, given up or bumped). The heard cells are the
  // network's as for every other tier (the axis-free cells are not taken for free here). A run
  // that never reaches that point is the same as without the option. Off: the run ends there.
  bool last_frontier_at_body_clearance = false;
  // @throws std::invalid_argument naming the field.
  void Validate() const;
};

// Seed 001's exploration controller. It owns the cognitive map: every new sonar ring goes through
// the sonar model into the log-odds grid at the current odometry pose. It first follows the room's
// boundary (wall on the left) for one circuit, then repeatedly rebuilds the partition map, goes
// round every obstacle rectangle not yet gone round (circle_obstacles), decays each visit count c
// to lambda c, counts a visit to the partition it is in, and drives to the free partition with the
// highest utility U = 1/c (K if never visited) along the graph's shortest x/y path, or over the
// grid when that path would pass closer than path_clearance_m to anything heard. A move that a
// close front echo (or an occupied cell of the grid) blocks puts the transition it was making into
// D. Once every free partition was visited it drives to the nearest unknown frontier it has not yet
// reached (the places live in the room as fitted, which misses what was never seen). It finishes
// when no obstacle, no place and no frontier is left, or after explore_max_s. A pressed bump panel
// marks the contact point for the planner, stops the wheels at once and backs the robot away from
// it. Otherwise the commanded wheel speeds change at most max_wheel_accel_rad_s2.
class SonarExplorer final : public robot::Controller {
 public:
  // @throws std::invalid_argument for invalid options.
  SonarExplorer(const robot::DiffDriveSpec& spec, const SonarExplorerOptions& options,
                std::shared_ptr<const SonarCellModel> model);

  // A time_s or X_WR_estimate that is not finite throws std::invalid_argument naming it, the
  // explorer unchanged; a tick whose time repeats or steps back changes no wheel speed.
  msgs::WheelSpeedCommand Update(const robot::ControllerInput& input) override;
  bool Finished() const override { return finished_; }
  // Why exploration ended: "map_complete" (no place and no frontier left that the robot can
  // reach), "time_limit" (explore_max_s), or "" while it goes on.
  const std::string& end_reason() const { return end_reason_; }
  // Controller time at which it ended (negative while it goes on).
  double end_time_s() const { return end_time_s_; }

  const LogOddsGrid& grid() const { return grid_; }
  // The map abstracted from the grid now (plus the failed moves in D), with the sonar axes'
  // long-range free space (BeamFreeGrid): the map the robot reports.
  CognitiveMap Map() const;
  // The same without the axes' free space: the map the robot plans on. The axes' evidence moves a
  // room side out past boxes the robot cannot pass and keeps a box 0.4-0.6 m from a wall off it;
  // planning on it sent the robot into those gaps (generated rooms: 29 instead of 20 of 150 runs
  // with a bumper contact, one with a 17 deg odometry error after it), so it changes what the map
  // says, not where the robot goes.
  CognitiveMap PlanningMap() const;
  const std::optional<msgs::Pose2D>& start() const { return start_; }
  // Whether the boundary-following phase is over.
  bool perimeter_done() const { return perimeter_done_; }
  // Obstacles gone round (or given up after circuit_max_s), as their rectangles were then.
  const std::vector<Rect>& circled_obstacles() const { return circled_; }
  // The circuits that closed: four boundary lines heard round the obstacle, corners where
  // consecutive ones meet (not yet used for the map's rectangles).
  const std::vector<ObstacleOutline>& closed_outlines() const { return outlines_; }
  int rings_integrated() const { return rings_integrated_; }
  // The run's decisions so far, in time order (exploration_event.h).
  const std::vector<ExplorationEvent>& events() const { return events_; }
  // Whether the robot is turning on the spot out of a wedge between two contacts
  // (bump_wedge_turns).
  bool turning_out_of_wedge() const { return wedge_heading_rad_.has_value(); }

 private:
  CognitiveMap BuildMap(const BeamFreeGrid* beam_free) const;
  // The reported map's room before the sides seen past are opened (open_sides_seen_past_m): the
  // room whose unknown share ends exploration, so that the option changes the map, not the run.
  Rect RoomAsFitted() const;
  // The wheel speeds wanted now, before the acceleration limit.
  msgs::WheelSpeedCommand Decide(const robot::ControllerInput& input);
  msgs::WheelSpeedCommand Explore(const robot::ControllerInput& input);
  msgs::WheelSpeedCommand DriveTo(const msgs::Pose2D& X_WR, const Eigen::Vector2d& target);
  // The first echo point (robot frame) in the corridor the body sweeps within stop_range_m.
  std::optional<Eigen::Vector2d> FrontBlocked(const msgs::RangeRing& ring) const;
  void Replan(const msgs::Pose2D& X_WR, double time_s);
  // Whether a target lies within visit_radius_m of one whose move a front echo blocked.
  bool Abandoned(const Eigen::Vector2d& target) const;
  // The grid's cells as free / occupied / unknown (fitted obstacles occupied; the unknown cells
  // under the robot's body free: it stands on them), and which of them
  // keep path_clearance_m from everything occupied, or from the occupied cells only (frontier
  // paths: a fitted obstacle may be a blob of space not yet seen); near the robot also the free
  // cells no nearer to those than its own cell (EscapeCells), so that it can leave.
  struct PlanningCells {
    CellMap cells;
    std::vector<char> safe;
    std::vector<char> safe_from_heard;
    // The same with narrow_clearance_m.
    std::vector<char> narrow_safe;
    std::vector<char> narrow_safe_from_heard;
    // safe_from_heard with squeeze_clearance_m (empty when it is 0).
    std::vector<char> squeeze_safe_from_heard;
    // safe_from_heard with robot_radius_m + front_margin_m (filled only for the last tier of
    // last_frontier_at_body_clearance, empty otherwise).
    std::vector<char> body_safe_from_heard;
  };
  // through_axis_free: the occupied cells the grid-aligned axes saw floor through count as free
  // (last_frontier_through_axis_free's last tier).
  // at_body_clearance: body_safe_from_heard is filled too (last_frontier_at_body_clearance's
  // tier).
  PlanningCells Planning(const Eigen::Vector2d& here, const std::vector<Rect>& obstacles,
                         bool through_axis_free, bool at_body_clearance = false) const;
  // Waypoints after the robot along the shortest traversable cell path to a goal cell: empty when
  // the robot's cell is a goal, nullopt when no goal can be reached.
  std::optional<std::vector<Eigen::Vector2d>> CellPath(const std::vector<char>& traversable,
                                                       const std::vector<char>& goal,
                                                       const Eigen::Vector2d& here) const;
  bool LegsClear(const PlanningCells& planning, const Eigen::Vector2d& here,
                 const std::vector<Eigen::Vector2d>& path) const;
  std::vector<Eigen::Vector2d> SafePathTo(const PlanningCells& planning, const CognitiveMap& map,
                                          const Eigen::Vector2d& here,
                                          const Eigen::Vector2d& target) const;
  // The shortest way over the `safe` cells inside the fitted room; empty when there is none.
  std::vector<Eigen::Vector2d> CellPathTo(const std::vector<char>& safe, const Rect& room,
                                          const Eigen::Vector2d& here,
                                          const Eigen::Vector2d& target) const;
  // Path (waypoints after the robot) to the nearest frontier not yet looked at over the free
  // `safe_from_heard` cells: empty when the robot stands on a goal already, nullopt when no
  // frontier is left or none can be reached.
  std::optional<std::vector<Eigen::Vector2d>> PlanToFrontier(
      const PlanningCells& planning, const std::vector<char>& safe_from_heard,
      const Eigen::Vector2d& here) const;
  // PlanToFrontier with path_clearance_m, else with narrow_clearance_m, else (when it is set)
  // with squeeze_clearance_m.
  std::optional<std::vector<Eigen::Vector2d>> PlanToAnyFrontier(const PlanningCells& planning,
                                                                const Eigen::Vector2d& here) const;
  // While a bump panel is pressed, and for bump_back_off_s after: the command backing away.
  std::optional<msgs::WheelSpeedCommand> ReactToBump(const robot::ControllerInput& input);
  // Whether an occupied grid cell lies in the corridor the body sweeps within stop_range_m.
  bool MapBlocksFront(const msgs::Pose2D& X_WR) const;
  // Whether the planner takes cell (ix, iy) for heard: P > 1 - eps, unless through_axis_free and
  // the grid-aligned axes saw floor through it at least map.beam_free_min_passes times.
  bool HeardForPlanning(int ix, int iy, bool through_axis_free) const;
  // The last tiers of the frontier search, tried in this order when the run would otherwise end
  // map_complete, each behind its option.
  enum class LastTier {
    kNone,
    kThroughAxisFree,  // last_frontier_through_axis_free: the axis-free cells taken for free
    kAtBodyClearance,  // last_frontier_at_body_clearance: free cells robot_radius_m +
                       // front_margin_m from the cells heard
  };
  // A path to a frontier by `tier`'s rule (not kNone), nullopt when there is none; notes the goal.
  std::optional<std::vector<Eigen::Vector2d>> PlanToLastTierFrontier(LastTier tier,
                                                                     const CognitiveMap& map,
                                                                     const Eigen::Vector2d& here);
  // The sideways offset (left positive) of the nearest contact point in that corridor, if any.
  std::optional<double> ContactAhead(const msgs::Pose2D& X_WR) const;

  robot::DiffDriveSpec spec_;
  SonarExplorerOptions options_;
  std::shared_ptr<const SonarCellModel> model_;
  LogOddsGrid grid_;
  BeamFreeGrid beam_free_;
  std::unique_ptr<robot::WallFollowingController> follower_;
  std::optional<msgs::Pose2D> start_;
  double last_ring_time_s_ = -1.0;
  int rings_integrated_ = 0;
  // Perimeter phase bookkeeping.
  bool perimeter_done_ = false;
  std::optional<double> last_theta_;
  double turned_rad_ = 0.0;
  double perimeter_travelled_m_ = 0.0;
  std::optional<Eigen::Vector2d> last_position_;
  std::optional<double> perimeter_start_s_;
  // Where the robot began turning without moving on, and how far it has turned since.
  std::optional<Eigen::Vector2d> spot_;
  double spot_turned_rad_ = 0.0;
  std::optional<double> explore_start_s_;
  // Visit counts live on the grid's cells so they survive re-partitioning.
  std::vector<double> visits_;
  std::vector<char> visited_;
  // Obstacle circuits: the corners still to reach of the one being gone round, and the
  // obstacles gone round (their rectangle when the circuit began).
  struct Circuit {
    Rect box;
    std::vector<Eigen::Vector2d> corners;
    double start_s = 0.0;
    // The end test's retry of skipped corners (of any obstacles; `box` unset): no outline is read
    // after it.
    bool retry = false;
  };
  std::optional<Circuit> circuit_;
  std::vector<Rect> circled_;
  // Circuit corners skipped after a blocked move (complete_room_check).
  std::vector<Eigen::Vector2d> skipped_corners_;
  std::vector<ObstacleOutline> outlines_;
  // The outline of the obstacle in `box` from the occupied cells round it; nullopt when a side
  // was never heard.
  std::optional<ObstacleOutline> OutlineHeard(const Rect& box) const;
  bool heading_to_circuit_ = false;
  // Sets path_ to the next circuit corner (starting a circuit round the nearest obstacle not yet
  // gone round when none is under way); false when every obstacle was gone round.
  bool PlanCircuit(const CognitiveMap& map, const PlanningCells& planning,
                   const Eigen::Vector2d& here, double time_s);
  // The reported room with the sides the robot has seen floor past opened (complete_room_check).
  Rect RoomJudged(const PlanningCells& planning) const;
  // Goes round the skipped circuit corners once more; true if a path to one was set.
  bool RetrySkippedCorners(const CognitiveMap& map, const PlanningCells& planning,
                           const Eigen::Vector2d& here, double time_s);
  // Waypoints over the free `clear` cells to the reachable one nearest `target`; empty when the
  // robot's own cell is that one (within waypoint_tolerance_m) or the robot's cell is off the grid.
  std::vector<Eigen::Vector2d> PathToward(const std::vector<char>& clear, const CellMap& cells,
                                          const Eigen::Vector2d& here,
                                          const Eigen::Vector2d& target) const;
  // The same over safe_from_heard, else over narrow_safe_from_heard.
  std::vector<Eigen::Vector2d> PathToward(const PlanningCells& planning,
                                          const Eigen::Vector2d& here,
                                          const Eigen::Vector2d& target) const;
  // A blocked move (front echo, occupied cell, bump): its transition goes into D and its target
  // is never tried again; a circuit corner's is skipped instead.
  void GiveUpMove(const Eigen::Vector2d& here, const char* why);
  // Appends an event at the current tick's time; a goal only when it differs from the last one
  // (its kind, or by a cell or more).
  void Note(const char* kind, const std::string& detail, const Eigen::Vector2d& at);
  // Marks the cells within frontier_view_m of `at` as looked at.
  void MarkLooked(const Eigen::Vector2d& at);
  std::vector<char> looked_;  // cells within frontier_view_m of a frontier goal the robot reached
  bool heading_to_frontier_ = false;
  // The last tier whose frontier the move under way goes to: until the move ends only such
  // frontiers are sought; kThroughAxisFree also frees the axis-free cells for the map check,
  // kAtBodyClearance drives at the back-off speed.
  LastTier last_tier_ = LastTier::kNone;
  // World points of echoes that blocked a move: occupied for the planner.
  std::vector<Eigen::Vector2d> blocking_echoes_;
  // Points bump panels touched: kept contact_clearance_m from by the planner.
  std::vector<Eigen::Vector2d> contacts_;
  double backing_off_until_s_ = -1.0;
  double backing_off_speed_m_s_ = 0.0;
  // The contact point the back-off under way (or ended within bump_back_off_s) leaves: a contact
  // on the far side of the robot from it is a wedge.
  std::optional<Eigen::Vector2d> backing_off_from_;
  // A turn on the spot out of a wedge: the heading it turns to and when it is given up.
  std::optional<double> wedge_heading_rad_;
  double wedge_turn_until_s_ = -1.0;
  // A pressed panel whose contact point lies on the far side of the robot from the one the back-off
  // leaves, while it runs or within bump_back_off_s after: starts the turn out of the wedge, true
  // if so.
  bool StartWedgeTurn(const robot::ControllerInput& input);
  // Where a pressed panel (of `panels` round the body) touched: on its centre line, 2 cm beyond
  // the body's radius.
  Eigen::Vector2d ContactPoint(const msgs::Pose2D& X_WR, int panel, int panels) const;
  // A bump: the contact point is in the way from now on and the move under way is abandoned.
  void KeepContactAndDropMove(const msgs::Pose2D& X_WR, const Eigen::Vector2d& contact);
  double last_replan_s_ = -1e9;
  double last_decay_s_ = -1.0;
  std::vector<Eigen::Vector2d> path_;
  int target_partition_ = -1;
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> failed_moves_;  // from, to points
  std::vector<Eigen::Vector2d> abandoned_;  // final targets of blocked moves: never tried again
  // Whether the given-up targets were tried once more (complete_unknown_share_max).
  bool abandoned_retried_ = false;
  bool finished_ = false;
  std::string end_reason_;
  double end_time_s_ = -1.0;
  std::vector<ExplorationEvent> events_;
  double now_s_ = 0.0;              // the current tick's time, for events_
  Eigen::Vector2d here_{0.0, 0.0};  // the robot's position at this tick, for events_
  void Finish(const char* reason, double time_s);
  msgs::WheelSpeedCommand command_;  // last command sent
  double last_command_s_ = -1.0;
};

}  // namespace plywood::perception
