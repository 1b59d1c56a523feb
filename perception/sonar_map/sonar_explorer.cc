#include "perception/sonar_map/sonar_explorer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "msgs/pose2d.h"
#include "msgs/shortest_number.h"
#include "perception/sonar_map/box_face_sides.h"
#include "perception/sonar_map/cell_dilation.h"
#include "perception/sonar_map/contact_clearance.h"
#include "perception/sonar_map/echo_gated_model.h"
#include "perception/sonar_map/escape_cells.h"
#include "perception/sonar_map/frontier_planner.h"
#include "perception/sonar_map/obstacle_circuit.h"
#include "perception/sonar_map/unknown_share.h"
#include "robot/drive/diff_drive_kinematics.h"

namespace plywood::perception {
namespace {

void RequirePositive(const std::string& field, double v) {
  if (!(std::isfinite(v) && v > 0.0))
    throw std::invalid_argument(field + ": must be a finite number > 0, got " +
                                msgs::ShortestNumber(v));
}

void RequireNonNegative(const std::string& field, double v) {
  if (!(std::isfinite(v) && v >= 0.0))
    throw std::invalid_argument(field + ": must be a finite number >= 0, got " +
                                msgs::ShortestNumber(v));
}

// A grid side beyond this many cells (the default is 160) would take gigabytes.
constexpr double kMaxGridCellsPerSide = 4000.0;

// Lengths that become cell or place counts: bounded so the counts fit an int and the grids fit
// in memory.
void RequireInRange(const std::string& field, double v, double low, double high) {
  if (!(v >= low && v <= high))
    throw std::invalid_argument(field + ": must be in [" + msgs::ShortestNumber(low) + ", " +
                                msgs::ShortestNumber(high) + "], got " + msgs::ShortestNumber(v));
}

Eigen::Vector2d Position(const msgs::Pose2D& X) { return {X.x_m, X.y_m}; }

// A heading error below this counts as aligned: DriveTo drives on from here.
constexpr double kAlignedRad = 0.2;
// Decay passes over the visit counts one replan makes one period at a time; the periods past
// this many are decayed at once, by lambda^n.
constexpr int kMaxDecayPasses = 64;

// Whether two of the map's obstacle rectangles are one obstacle: they overlap, or lie less than
// `same_m` apart (the map is refitted at every replan, and joins or grows its rectangles).
bool SameObstacle(const Rect& a, const Rect& b, double same_m) {
  return std::min(a.x1, b.x1) - std::max(a.x0, b.x0) > -same_m &&
         std::min(a.y1, b.y1) - std::max(a.y0, b.y0) > -same_m;
}

// These lengths become counts of grid cells (a dilation's radius, a gap, a peel): beyond the
// grid's diagonal every cell lies within them of any other, so a longer one changes nothing but
// the time (path_clearance_m 20 m in seed 001's 8 m grid ran > 100 s, 0.9 s at 0.45 m), and past
// 1e8 m the count no longer fits an int (s60: frontier_wall_band_m 1e300 dropped the band, the
// tour ended 28 s later; obstacle_join_m 1e300 stopped the run after it with
// "plywood: max_gap: must be >= 0").
void RequireLengthsWithinTheGrid(const SonarExplorerOptions& o) {
  const double diagonal_m = 2.0 * std::numbers::sqrt2 * o.grid_half_extent_m;
  for (const auto& [name, length_m] : {std::pair{"path_clearance_m", o.path_clearance_m},
                                       std::pair{"frontier_wall_band_m", o.frontier_wall_band_m},
                                       std::pair{"obstacle_join_m", o.map.obstacle_join_m},
                                       std::pair{"obstacle_peel_net_free_clearance_m",
                                                 o.map.obstacle_peel_net_free_clearance_m}}) {
    if (length_m <= diagonal_m) continue;
    throw std::invalid_argument(
        std::string(name) + ": must be at most the grid's diagonal, " +
        msgs::ShortestNumber(diagonal_m) +
        " m (2 sqrt(2) grid_half_extent_m: every cell lies within it of any other), got " +
        msgs::ShortestNumber(length_m));
  }
}

}  // namespace

void SonarExplorerOptions::Validate() const {
  // The beam-free grid's options are read as beam_free_<field>: its own messages name <field>
  // alone, which is no key a user can find.
  try {
    beam_free.Validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("beam_free_") + e.what());
  }
  if (sonar_model != "net" && sonar_model != "classical")
    throw std::invalid_argument("sonar_model: must be net or classical, got '" + sonar_model + "'");
  if (sonar_model == "net" && weights_file.empty())
    throw std::invalid_argument("weights_file: needed when sonar_model is net");
  RequireInRange("grid_half_extent_m", grid_half_extent_m, 0.5, 100.0);
  RequireInRange("grid_resolution_m", grid_resolution_m, 0.01, 1.0);
  if (2.0 * grid_half_extent_m / grid_resolution_m > kMaxGridCellsPerSide)
    throw std::invalid_argument(
        "grid_resolution_m: the grid would be " +
        msgs::ShortestNumber(std::ceil(2.0 * grid_half_extent_m / grid_resolution_m)) +
        " cells wide (2 grid_half_extent_m / grid_resolution_m), more than " +
        msgs::ShortestNumber(kMaxGridCellsPerSide));
  if (!(p_min > 0.0 && p_min < 0.5)) throw std::invalid_argument("p_min: must be in (0, 0.5)");
  RequirePositive("log_odds_limit", log_odds_limit);
  map.Validate();
  RequirePositive("wall_distance_m", wall_distance_m);
  // The perimeter follower takes side points beyond its max_wall_range_m for no wall; nearer than
  // the distance it keeps, it refused itself naming that field, which is no key of this controller.
  if (const double reach_m = robot::WallFollowingOptions{}.max_wall_range_m;
      !(wall_distance_m < reach_m))
    throw std::invalid_argument(
        "wall_distance_m: must be below " + msgs::ShortestNumber(reach_m) +
        " m, the range beyond which the perimeter follower takes nothing for the wall, got " +
        msgs::ShortestNumber(wall_distance_m));
  RequirePositive("perimeter_turn_rad", perimeter_turn_rad);
  RequirePositive("perimeter_max_s", perimeter_max_s);
  RequirePositive("perimeter_stuck_turn_rad", perimeter_stuck_turn_rad);
  RequirePositive("perimeter_front_clearance_m", perimeter_front_clearance_m);
  RequirePositive("speed_m_s", speed_m_s);
  RequirePositive("turn_rate_rad_s", turn_rate_rad_s);
  RequirePositive("replan_period_s", replan_period_s);
  if (!(visit_decay > 0.0 && visit_decay <= 1.0))
    throw std::invalid_argument("visit_decay: must be in (0, 1]");
  RequirePositive("unvisited_utility", unvisited_utility);
  RequireInRange("visit_radius_m", visit_radius_m, 0.01, 10.0);
  RequireInRange("place_size_m", place_size_m, 0.1, 100.0);
  RequireNonNegative("perimeter_min_m", perimeter_min_m);
  RequirePositive("clearance_m", clearance_m);
  RequirePositive("stop_range_m", stop_range_m);
  RequirePositive("max_wheel_accel_rad_s2", max_wheel_accel_rad_s2);
  RequirePositive("bump_back_off_s", bump_back_off_s);
  RequirePositive("bump_back_off_speed_m_s", bump_back_off_speed_m_s);
  RequireNonNegative("front_margin_m", front_margin_m);
  RequirePositive("waypoint_tolerance_m", waypoint_tolerance_m);
  RequirePositive("explore_max_s", explore_max_s);
  if (frontier_min_cells < 1)
    throw std::invalid_argument("frontier_min_cells: must be >= 1, got " +
                                std::to_string(frontier_min_cells));
  RequirePositive("robot_radius_m", robot_radius_m);
  RequirePositive("path_clearance_m", path_clearance_m);
  if (!(path_clearance_m > robot_radius_m))
    throw std::invalid_argument("path_clearance_m: must be > robot_radius_m");
  if (!(robot_radius_m + front_margin_m < path_clearance_m))
    throw std::invalid_argument(
        "front_margin_m: robot_radius_m + front_margin_m must be < path_clearance_m");
  if (!(narrow_clearance_m > robot_radius_m + front_margin_m &&
        narrow_clearance_m <= path_clearance_m))
    throw std::invalid_argument(
        "narrow_clearance_m: must be > robot_radius_m + front_margin_m and <= path_clearance_m, "
        "got " +
        msgs::ShortestNumber(narrow_clearance_m));
  if (squeeze_clearance_m != 0.0 && !(squeeze_clearance_m > robot_radius_m + front_margin_m &&
                                      squeeze_clearance_m <= narrow_clearance_m))
    throw std::invalid_argument(
        "squeeze_clearance_m: must be 0 or > robot_radius_m + front_margin_m and <= "
        "narrow_clearance_m, got " +
        msgs::ShortestNumber(squeeze_clearance_m));
  if (contact_clearance_m != 0.0 &&
      !(contact_clearance_m > robot_radius_m && contact_clearance_m <= 10.0))
    throw std::invalid_argument(
        "contact_clearance_m: must be 0 or > robot_radius_m (and <= 10), got " +
        msgs::ShortestNumber(contact_clearance_m));
  RequireInRange("frontier_view_m", frontier_view_m, 0.01, 10.0);
  RequireNonNegative("frontier_wall_band_m", frontier_wall_band_m);
  if (!(frontier_view_m > waypoint_tolerance_m))
    throw std::invalid_argument("frontier_view_m: must be > waypoint_tolerance_m");
  RequireInRange("circuit_reach_m", circuit_reach_m, waypoint_tolerance_m, 1.0);
  RequirePositive("circuit_max_s", circuit_max_s);
  RequireNonNegative("circuit_same_m", circuit_same_m);
  RequireLengthsWithinTheGrid(*this);
  if (!(complete_unknown_share_max > 0.0 && complete_unknown_share_max <= 1.0))
    throw std::invalid_argument("complete_unknown_share_max: must be in (0, 1], got " +
                                msgs::ShortestNumber(complete_unknown_share_max));
}

SonarExplorer::SonarExplorer(const robot::DiffDriveSpec& spec, const SonarExplorerOptions& options,
                             std::shared_ptr<const SonarCellModel> model)
    : spec_(spec), options_(options), model_(std::move(model)) {
  spec_.Validate();
  options_.Validate();
  robot::internal::RequireDrivableSpeed(spec_, "speed_m_s", options_.speed_m_s);
  robot::internal::RequireDrivableSpeed(spec_, "bump_back_off_speed_m_s",
                                        options_.bump_back_off_speed_m_s);
  if (!model_) throw std::invalid_argument("sonar_model: no model given");
  if (options_.misses_say_nothing) model_ = std::make_shared<EchoGatedModel>(model_);
  robot::WallFollowingOptions follow;
  follow.side = robot::WallSide::kLeft;
  follow.distance_m = options_.wall_distance_m;
  follow.speed_m_s = options_.speed_m_s;
  follow.front_clearance_m = options_.perimeter_front_clearance_m;
  follower_ = std::make_unique<robot::WallFollowingController>(spec_, follow);
}

CognitiveMap SonarExplorer::Map() const {
  // Before the first update the grids are not laid out yet (and nothing was heard).
  return BuildMap(start_ ? &beam_free_ : nullptr);
}

CognitiveMap SonarExplorer::PlanningMap() const { return BuildMap(nullptr); }

Rect SonarExplorer::RoomAsFitted() const {
  if (options_.map.open_sides_seen_past_m <= 0.0) return Map().room;
  CognitiveMapOptions fitted = options_.map;
  fitted.open_sides_seen_past_m = 0.0;
  const Eigen::Vector2d inside =
      start_ ? Position(*start_) : grid_.CellCentre(grid_.width() / 2, grid_.height() / 2);
  return BuildCognitiveMap(grid_, inside, fitted, start_ ? &beam_free_ : nullptr).room;
}

CognitiveMap SonarExplorer::BuildMap(const BeamFreeGrid* beam_free) const {
  const Eigen::Vector2d inside =
      start_ ? Position(*start_) : grid_.CellCentre(grid_.width() / 2, grid_.height() / 2);
  CognitiveMap map = BuildCognitiveMap(grid_, inside, options_.map, beam_free);
  // Failed moves: the transition between the partitions at either end goes into D.
  for (const auto& [from, to] : failed_moves_) {
    const int a = map.partitions.Find(from), b = map.partitions.Find(to);
    if (a >= 0 && b >= 0 && a != b) map.negative.Forbid(a, b);
  }
  map.graph = BuildGraph(map.partitions, map.adjacency, map.negative);
  return map;
}

std::optional<Eigen::Vector2d> SonarExplorer::FrontBlocked(const msgs::RangeRing& ring) const {
  // The echo points in the corridor the robot body sweeps ahead. The sonars up to 60 deg off the
  // axis are looked at, since an obstacle corner met at an angle is heard only by the oblique
  // ones; but on the Magellan Pro's ring (0.1435 m) a 45 deg echo lies >= 0.25 m to the side even
  // at the 0.15 m minimum range, beyond the body's sweep: there only the 0 and 22.5 deg sonars can
  // block (docs/sonar_map/history.md, round 67b).
  const double kRadius = options_.robot_radius_m;
  const double kSideMargin = options_.front_margin_m;  // corridor half-width = radius + this
  for (const auto& r : ring.readings) {
    const double bearing = msgs::WrapAngle(r.X_RS.theta_rad);
    if (!r.echo || std::abs(bearing) > 1.05) continue;
    const double along = r.X_RS.x_m + r.range_m * std::cos(bearing);
    const double side = r.X_RS.y_m + r.range_m * std::sin(bearing);
    // An echo is placed on its sonar's axis but may come from anywhere in the cone: an oblique
    // sonar's echo beside the body (a corner being passed) blocks only inside the body's sweep.
    const double half_width = std::abs(bearing) > 0.5 ? kRadius : kRadius + kSideMargin;
    if (along > 0.0 && along < options_.stop_range_m + kRadius && std::abs(side) < half_width)
      return Eigen::Vector2d(along, side);
  }
  return std::nullopt;
}

msgs::WheelSpeedCommand SonarExplorer::DriveTo(const msgs::Pose2D& X_WR,
                                               const Eigen::Vector2d& target) {
  const Eigen::Vector2d d = target - Position(X_WR);
  const double heading_error = msgs::WrapAngle(std::atan2(d.y(), d.x()) - X_WR.theta_rad);
  robot::BodyTwist twist;
  const double w =
      std::clamp(2.0 * heading_error, -options_.turn_rate_rad_s, options_.turn_rate_rad_s);
  twist.angular_rad_s = w;
  // Trajectories parallel to x or y: turn on the spot first, drive once aligned.
  // A move through a gap at the body's own clearance goes at the back-off speed: a face the sonar
  // placed a few centimetres off is met at the speed a touch is left at.
  const double speed = last_tier_ == LastTier::kAtBodyClearance
                           ? std::min(options_.speed_m_s, options_.bump_back_off_speed_m_s)
                           : options_.speed_m_s;
  if (std::abs(heading_error) < kAlignedRad) twist.linear_m_s = std::min(speed, 0.1 + d.norm());
  return robot::TwistToWheelSpeeds(spec_, twist);
}

void SonarExplorer::Replan(const msgs::Pose2D& X_WR, double time_s) {
  CognitiveMap map = PlanningMap();
  // Places: the free partitions cut into pieces no larger than place_size_m, so that a room the
  // sonar has not yet divided still has somewhere to go; D and the graph follow the pieces.
  {
    PartitionMap places;
    for (const Partition& p : map.partitions.partitions()) {
      if (p.label != Label::kFree) {
        places.mutable_partitions().push_back(p);
        continue;
      }
      const int nx =
          std::max(1, static_cast<int>(std::ceil((p.rect.x1 - p.rect.x0) / options_.place_size_m)));
      const int ny =
          std::max(1, static_cast<int>(std::ceil((p.rect.y1 - p.rect.y0) / options_.place_size_m)));
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          const double w = (p.rect.x1 - p.rect.x0) / nx, h = (p.rect.y1 - p.rect.y0) / ny;
          places.mutable_partitions().push_back({{p.rect.x0 + i * w, p.rect.y0 + j * h,
                                                  p.rect.x0 + (i + 1) * w, p.rect.y0 + (j + 1) * h},
                                                 Label::kFree});
        }
    }
    map.partitions = places;
    map.adjacency = map.partitions.Adjacencies(1e-6);
    map.negative = InitialNegativeExperience(map.partitions, map.adjacency, 0.0);
    for (const auto& [from, to] : failed_moves_) {
      const int a = map.partitions.Find(from), b = map.partitions.Find(to);
      if (a >= 0 && b >= 0 && a != b) map.negative.Forbid(a, b);
    }
    map.graph = BuildGraph(map.partitions, map.adjacency, map.negative);
  }
  const Eigen::Vector2d here = Position(X_WR);
  // lambda per replan period, however often a blocked move makes the robot replan: otherwise
  // 1/c of a visited place outgrows K within seconds.
  // A period far below the time between replans (replan_period_s 1e-9: 1e8 passes over the grid
  // per control step, and below the clock's last digit last_decay_s_ + period never moved, so the
  // run hung for ever) decays the periods past kMaxDecayPasses at once, by lambda^n.
  int passes = 0;
  while (time_s - last_decay_s_ >= options_.replan_period_s) {
    if (++passes > kMaxDecayPasses) {
      const double periods = std::floor((time_s - last_decay_s_) / options_.replan_period_s);
      const double factor = std::pow(options_.visit_decay, periods);
      for (double& c : visits_) c *= factor;
      last_decay_s_ = time_s - std::fmod(time_s - last_decay_s_, options_.replan_period_s);
      break;
    }
    for (double& c : visits_) c *= options_.visit_decay;
    last_decay_s_ = last_decay_s_ < 0.0 ? time_s : last_decay_s_ + options_.replan_period_s;
  }
  const Eigen::Vector2i cell = grid_.CellAt(here);
  if (cell.x() >= 0) visits_[cell.y() * grid_.width() + cell.x()] += 1.0;
  if (last_tier_ != LastTier::kNone) {
    // On the way to a frontier a last tier found: only such frontiers are sought until the move
    // ends, so that the goal does not flip between the two rules.
    heading_to_circuit_ = false;
    target_partition_ = -1;
    if (std::optional<std::vector<Eigen::Vector2d>> frontier =
            PlanToLastTierFrontier(last_tier_, map, here)) {
      path_ = std::move(*frontier);
      heading_to_frontier_ = true;
      return;
    }
    last_tier_ = LastTier::kNone;
  }
  const PlanningCells planning = Planning(here, map.obstacles, false);
  heading_to_circuit_ = false;
  if (options_.circle_obstacles && PlanCircuit(map, planning, here, time_s)) {
    heading_to_frontier_ = false;
    target_partition_ = -1;
    return;
  }
  const auto& parts = map.partitions.partitions();
  double best_u = -1.0, best_d = std::numeric_limits<double>::infinity();
  bool best_unvisited = false;
  int best = -1;
  for (int node : map.graph.nodes) {
    const Rect& r = parts[node].rect;
    // The target: the centre, kept clear of the room walls.
    const Rect shrunk{map.room.x0 + options_.clearance_m, map.room.y0 + options_.clearance_m,
                      map.room.x1 - options_.clearance_m, map.room.y1 - options_.clearance_m};
    Eigen::Vector2d t = r.Centre();
    if (shrunk.x1 > shrunk.x0) t.x() = std::clamp(t.x(), shrunk.x0, shrunk.x1);
    if (shrunk.y1 > shrunk.y0) t.y() = std::clamp(t.y(), shrunk.y0, shrunk.y1);
    bool clear = true;
    for (const Rect& o : map.obstacles) {
      if (t.x() > o.x0 - options_.clearance_m && t.x() < o.x1 + options_.clearance_m &&
          t.y() > o.y0 - options_.clearance_m && t.y() < o.y1 + options_.clearance_m)
        clear = false;
    }
    if (!clear || map.partitions.Find(t) < 0 || Abandoned(t)) continue;
    const Eigen::Vector2i tc = grid_.CellAt(t);
    if (tc.x() < 0) continue;
    const bool unvisited = !visited_[tc.y() * grid_.width() + tc.x()];
    double c = 0.0;
    for (int iy = 0; iy < grid_.height(); ++iy)
      for (int ix = 0; ix < grid_.width(); ++ix)
        if (visits_[iy * grid_.width() + ix] > 0.0 && r.Contains(grid_.CellCentre(ix, iy)))
          c += visits_[iy * grid_.width() + ix];
    const double u = c > 0.0 ? 1.0 / c : options_.unvisited_utility;
    const double dist = std::abs(t.x() - here.x()) + std::abs(t.y() - here.y());
    if (dist < options_.visit_radius_m) continue;  // already here
    // Places never reached come first (the seed's K), then the utility, then the distance.
    const bool better =
        unvisited != best_unvisited
            ? unvisited
            : (u > best_u + 1e-12 || (std::abs(u - best_u) <= 1e-12 && dist < best_d));
    if (best < 0 || better) {
      const std::vector<Eigen::Vector2d> path = SafePathTo(planning, map, here, t);
      if (path.empty()) continue;
      best_u = u;
      best_d = dist;
      best_unvisited = unvisited;
      best = node;
      path_ = path;
    }
  }
  target_partition_ = best;
  heading_to_frontier_ = false;
  if (best < 0) path_.clear();
  if (!best_unvisited) {
    // No reachable place left that was never visited: on to the unknown frontiers, and finish
    // when none is left either. Standing on a frontier goal already (the robot came to rest a few
    // centimetres past where it marked one) is arriving there: look from here and from the centre
    // of the robot's cell, which the goal test measures from; then no goal is left in that cell.
    std::optional<std::vector<Eigen::Vector2d>> frontier = PlanToAnyFrontier(planning, here);
    if (frontier && frontier->empty()) {
      MarkLooked(here);
      MarkLooked(grid_.CellCentre(cell.x(), cell.y()));
      frontier = PlanToAnyFrontier(planning, here);
    }
    // Nothing left, but more of the room the robot reports unknown than complete_unknown_share_max
    // allows: the goals given up after blocked moves are tried once more (the blocked legs often
    // stopped on a face beyond their ends, from one spot).
    // With complete_room_check the share is measured past the sides the robot has seen floor
    // beyond, and the skipped circuit corners are given up too.
    const bool check_room = options_.complete_room_check;
    const bool anything_given_up = !abandoned_.empty() || (check_room && !skipped_corners_.empty());
    if (!(frontier && !frontier->empty()) && !abandoned_retried_ && anything_given_up &&
        options_.complete_unknown_share_max < 1.0 &&
        UnknownShareOfRoom(planning.cells, grid_,
                           check_room ? RoomJudged(planning) : RoomAsFitted()) >
            options_.complete_unknown_share_max) {
      std::vector<Eigen::Vector2d> given_up;
      given_up.swap(abandoned_);
      frontier = PlanToAnyFrontier(planning, here);
      if (frontier && !frontier->empty()) {
        abandoned_retried_ = true;
      } else if (check_room && RetrySkippedCorners(map, planning, here, time_s)) {
        abandoned_retried_ = true;
        heading_to_frontier_ = false;
        target_partition_ = -1;
        return;
      } else {
        abandoned_ = std::move(given_up);
      }
    }
    if (frontier && !frontier->empty()) {
      path_ = std::move(*frontier);
      heading_to_frontier_ = true;
      target_partition_ = -1;
      Note("goal", "frontier", path_.back());
      return;
    }
    for (const auto& [on, tier] :
         {std::pair{options_.last_frontier_through_axis_free, LastTier::kThroughAxisFree},
          std::pair{options_.last_frontier_at_body_clearance, LastTier::kAtBodyClearance}}) {
      if (!on) continue;
      if (std::optional<std::vector<Eigen::Vector2d>> last =
              PlanToLastTierFrontier(tier, map, here)) {
        path_ = std::move(*last);
        heading_to_frontier_ = true;
        last_tier_ = tier;
        target_partition_ = -1;
        return;
      }
    }
    Finish("map_complete", time_s);
    return;
  }
  if (!path_.empty()) Note("goal", "place", path_.back());
}

bool SonarExplorer::PlanCircuit(const CognitiveMap& map, const PlanningCells& planning,
                                const Eigen::Vector2d& here, double time_s) {
  for (;;) {
    if (!circuit_) {
      // The nearest obstacle not gone round yet.
      const Rect* next = nullptr;
      for (const Rect& o : map.obstacles) {
        bool done = false;
        // The map is refitted at every replan: a rectangle overlapping one gone round is that
        // obstacle seen better (or joined to a neighbour), not a new one.
        for (const Rect& c : circled_) done = done || SameObstacle(o, c, options_.circuit_same_m);
        if (done) continue;
        if (next == nullptr || (o.Centre() - here).norm() < (next->Centre() - here).norm())
          next = &o;
      }
      if (next == nullptr) return false;
      circled_.push_back(*next);
      circuit_ = Circuit{*next, CircuitAround(*next, options_.wall_distance_m, here), time_s};
      // Back to the first corner: the circuit is closed when the robot is where it began it.
      circuit_->corners.push_back(circuit_->corners.front());
    }
    if (time_s - circuit_->start_s > options_.circuit_max_s) circuit_->corners.clear();
    while (!circuit_->corners.empty()) {
      const Eigen::Vector2d corner = circuit_->corners.front();
      if ((corner - here).norm() >= options_.circuit_reach_m) {
        std::vector<Eigen::Vector2d> path = PathToward(planning, here, corner);
        if (!path.empty()) {
          path_ = std::move(path);
          heading_to_circuit_ = true;
          Note("goal", "circuit_corner", corner);
          return true;
        }
      }
      // Reached, or as near as the free space lets the robot come: on to the next corner.
      circuit_->corners.erase(circuit_->corners.begin());
    }
    // The faces are read round the obstacle as the map holds it now: the rectangle the circuit
    // was planned on can be a first piece of one face (with the sensors in step, 0.2 x 0.1 m of
    // a 0.57 m box in seed001_room_4), and a window round that left the far face outside it.
    if (!circuit_->retry) {
      Rect grown = circuit_->box;
      for (const Rect& o : map.obstacles) {
        if (SameObstacle(o, grown, options_.circuit_same_m)) {
          grown = Rect{std::min(grown.x0, o.x0), std::min(grown.y0, o.y0), std::max(grown.x1, o.x1),
                       std::max(grown.y1, o.y1)};
        }
      }
      if (std::optional<ObstacleOutline> outline = OutlineHeard(grown))
        outlines_.push_back(*outline);
    }
    circuit_.reset();
  }
}

Rect SonarExplorer::RoomJudged(const PlanningCells& planning) const {
  // Floor past a side: seen free the body's width along it, and deeper than the sonar's range
  // noise (what the axes' free space already stops short by), so that a wall's far edge read free
  // is not floor.
  const Rect room = RoomAsFitted();
  return OpenSides(room,
                   SidesSeenPast(planning.cells, grid_, start_ ? &beam_free_ : nullptr,
                                 options_.map.beam_free_min_passes, room,
                                 2.0 * options_.robot_radius_m, options_.beam_free.stop_short_m),
                   grid_);
}

bool SonarExplorer::RetrySkippedCorners(const CognitiveMap& map, const PlanningCells& planning,
                                        const Eigen::Vector2d& here, double time_s) {
  if (skipped_corners_.empty()) return false;
  // One circuit through every skipped corner, in the order they were skipped.
  Circuit retry{Rect{}, std::move(skipped_corners_), time_s, true};
  skipped_corners_.clear();
  circuit_ = std::move(retry);
  return PlanCircuit(map, planning, here, time_s);
}

std::vector<Eigen::Vector2d> SonarExplorer::PathToward(const PlanningCells& planning,
                                                       const Eigen::Vector2d& here,
                                                       const Eigen::Vector2d& target) const {
  // Keeping path_clearance_m from what was heard where that gets nearer, narrow_clearance_m
  // otherwise (a gap the robot can pass but not with the wide margin).
  std::vector<Eigen::Vector2d> path =
      PathToward(planning.safe_from_heard, planning.cells, here, target);
  if (path.empty() && options_.circuit_narrow)
    path = PathToward(planning.narrow_safe_from_heard, planning.cells, here, target);
  return path;
}

std::vector<Eigen::Vector2d> SonarExplorer::PathToward(const std::vector<char>& clear,
                                                       const CellMap& cells,
                                                       const Eigen::Vector2d& here,
                                                       const Eigen::Vector2d& target) const {
  const int W = grid_.width(), H = grid_.height();
  const Eigen::Vector2i start = grid_.CellAt(here);
  if (start.x() < 0) return {};
  std::vector<char> traversable(clear.size(), 0);
  for (std::size_t i = 0; i < traversable.size(); ++i)
    traversable[i] = clear[i] && cells.cells[i] == CellState::kFree;
  // The reachable cells (8-connected flood from the robot's cell), and the one nearest the target.
  std::vector<char> reached(traversable.size(), 0);
  std::vector<Eigen::Vector2i> stack{start};
  reached[static_cast<std::size_t>(start.y()) * W + start.x()] = 1;
  Eigen::Vector2i best = start;
  double best_d = (grid_.CellCentre(start.x(), start.y()) - target).norm();
  while (!stack.empty()) {
    const Eigen::Vector2i c = stack.back();
    stack.pop_back();
    const double d = (grid_.CellCentre(c.x(), c.y()) - target).norm();
    const long ci = static_cast<long>(c.y()) * W + c.x(),
               bi = static_cast<long>(best.y()) * W + best.x();
    if (d < best_d - 1e-12 || (std::abs(d - best_d) <= 1e-12 && ci < bi)) {
      best_d = d;
      best = c;
    }
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = c.x() + dx, ny = c.y() + dy;
        if (nx < 0 || ny < 0 || nx >= W || ny >= H) continue;
        const std::size_t ni = static_cast<std::size_t>(ny) * W + nx;
        if (reached[ni] || !traversable[ni]) continue;
        reached[ni] = 1;
        stack.push_back({nx, ny});
      }
  }
  // No nearer place to be: where the robot stands is as close as it gets.
  if ((here - target).norm() - best_d < options_.waypoint_tolerance_m) return {};
  std::vector<char> goal(traversable.size(), 0);
  goal[static_cast<std::size_t>(best.y()) * W + best.x()] = 1;
  return CellPath(traversable, goal, here).value_or(std::vector<Eigen::Vector2d>{});
}

std::optional<ObstacleOutline> SonarExplorer::OutlineHeard(const Rect& box) const {
  // The occupied cells round the box, out to half the wall distance: its faces as heard.
  const double margin = 0.5 * options_.wall_distance_m;
  std::vector<Eigen::Vector2d> heard;
  for (int iy = 0; iy < grid_.height(); ++iy)
    for (int ix = 0; ix < grid_.width(); ++ix) {
      const Eigen::Vector2d c = grid_.CellCentre(ix, iy);
      if (c.x() > box.x0 - margin && c.x() < box.x1 + margin && c.y() > box.y0 - margin &&
          c.y() < box.y1 + margin && grid_.Probability(ix, iy) > 1.0 - options_.map.eps)
        heard.push_back(c);
    }
  constexpr int kMinPointsPerSide = 3;
  return OutlineFromBoundary(heard, grid_.resolution_m(), options_.map.fit_sigma_m,
                             kMinPointsPerSide);
}

void SonarExplorer::Note(const char* kind, const std::string& detail, const Eigen::Vector2d& at) {
  if (std::string(kind) == "goal") {
    for (auto it = events_.rbegin(); it != events_.rend(); ++it) {
      if (it->kind != "goal") continue;
      // The same goal again, or the same place refitted by less than a cell.
      if (it->detail == detail && (it->at - at).norm() < grid_.resolution_m()) return;
      break;
    }
  }
  events_.push_back({now_s_, kind, detail, at});
}

void SonarExplorer::GiveUpMove(const Eigen::Vector2d& here, const char* why) {
  Note("given_up", why, here);
  last_tier_ = LastTier::kNone;
  if (heading_to_circuit_) {
    // The way to this circuit corner is blocked: the circuit goes on from the next one.
    if (circuit_ && !circuit_->corners.empty()) {
      if (options_.complete_room_check) skipped_corners_.push_back(circuit_->corners.front());
      circuit_->corners.erase(circuit_->corners.begin());
    }
    heading_to_circuit_ = false;
    return;
  }
  failed_moves_.emplace_back(here, path_.front());
  abandoned_.push_back(path_.back());
}

void SonarExplorer::Finish(const char* reason, double time_s) {
  Note("finish", reason, here_);
  finished_ = true;
  end_reason_ = reason;
  end_time_s_ = time_s;
}

void SonarExplorer::MarkLooked(const Eigen::Vector2d& at) {
  const Eigen::Vector2i c = grid_.CellAt(at);
  if (c.x() < 0) return;
  const int v = static_cast<int>(std::ceil(options_.frontier_view_m / grid_.resolution_m()));
  for (int dy = -v; dy <= v; ++dy)
    for (int dx = -v; dx <= v; ++dx) {
      const int ix = c.x() + dx, iy = c.y() + dy;
      if (grid_.Contains(ix, iy) &&
          (grid_.CellCentre(ix, iy) - at).norm() <= options_.frontier_view_m)
        looked_[iy * grid_.width() + ix] = 1;
    }
}

bool SonarExplorer::Abandoned(const Eigen::Vector2d& target) const {
  for (const Eigen::Vector2d& a : abandoned_)
    if ((a - target).norm() < options_.visit_radius_m) return true;
  return false;
}

SonarExplorer::PlanningCells SonarExplorer::Planning(const Eigen::Vector2d& here,
                                                     const std::vector<Rect>& obstacles,
                                                     bool through_axis_free,
                                                     bool at_body_clearance) const {
  const int W = grid_.width(), H = grid_.height();
  const double res = grid_.resolution_m(), eps = options_.map.eps;
  PlanningCells out;
  out.cells = CellMap{W, H, std::vector<CellState>(static_cast<std::size_t>(W) * H)};
  std::vector<char> occupied(out.cells.cells.size(), 0), heard(out.cells.cells.size(), 0);
  std::vector<char> touched(out.cells.cells.size(), 0);
  for (const Eigen::Vector2d& p : contacts_) {
    const Eigen::Vector2i c = grid_.CellAt(p);
    if (c.x() >= 0) touched[static_cast<std::size_t>(c.y()) * W + c.x()] = 1;
  }
  // The cells of the blocking echoes, found once rather than compared with every cell.
  std::vector<char> echo_cell(out.cells.cells.size(), 0);
  for (const Eigen::Vector2d& e : blocking_echoes_) {
    const Eigen::Vector2i c = grid_.CellAt(e);
    if (c.x() >= 0) echo_cell[static_cast<std::size_t>(c.y()) * W + c.x()] = 1;
  }
  for (int iy = 0; iy < H; ++iy)
    for (int ix = 0; ix < W; ++ix) {
      const std::size_t i = static_cast<std::size_t>(iy) * W + ix;
      const double p = grid_.Probability(ix, iy);
      CellState state =
          p < eps ? CellState::kFree : (p > 1.0 - eps ? CellState::kOccupied : CellState::kUnknown);
      if (state == CellState::kOccupied && !HeardForPlanning(ix, iy, through_axis_free))
        state = CellState::kFree;
      // The robot's body stands on the cells under it: they are free whatever the sonar made of
      // them (it never hears inside its blanking range, so a cell the robot came to stand on may
      // still be unknown). Left unknown, they can cut the robot's own cell off from the free space
      // around it, and then nothing is reachable and the run ended "map_complete" on the spot.
      if (state == CellState::kUnknown &&
          (grid_.CellCentre(ix, iy) - here).norm() <= options_.robot_radius_m)
        state = CellState::kFree;
      out.cells.cells[i] = state;
      // The fitted obstacles are no way through, but their unknown cells stay unknown: a blob
      // fitted around space nobody has seen yet is where the frontier is.
      bool in_obstacle = false;
      for (const Rect& o : obstacles)
        in_obstacle = in_obstacle || o.Contains(grid_.CellCentre(ix, iy));
      heard[i] = state == CellState::kOccupied || echo_cell[i];
      occupied[i] = heard[i] || in_obstacle;
    }
  const double contact_cells = options_.contact_clearance_m / res;
  const auto blocked = [&](const std::vector<char>& mask, double clearance_m) {
    return BlockedCells(mask, touched, W, H, clearance_m / res, contact_cells);
  };
  const std::vector<char> near = blocked(occupied, options_.path_clearance_m);
  const std::vector<char> near_heard = blocked(heard, options_.path_clearance_m);
  const std::vector<char> narrow = blocked(occupied, options_.narrow_clearance_m);
  const std::vector<char> narrow_heard = blocked(heard, options_.narrow_clearance_m);
  const std::vector<char> squeeze_heard = options_.squeeze_clearance_m > 0.0
                                              ? blocked(heard, options_.squeeze_clearance_m)
                                              : std::vector<char>{};
  const double body_clearance_m = options_.robot_radius_m + options_.front_margin_m;
  const std::vector<char> body_heard =
      at_body_clearance ? blocked(heard, body_clearance_m) : std::vector<char>{};
  // A robot backing off a contact leaves getting no nearer to it either.
  for (std::size_t i = 0; i < touched.size(); ++i) {
    heard[i] = heard[i] || touched[i];
    occupied[i] = occupied[i] || touched[i];
  }
  // The robot may be closer than the clearance to something (after a blocked move, in a narrow
  // passage): the free cells within path_clearance_m of it stay usable so that it can leave, as
  // long as they are no nearer to what that clearance keeps it from than its own cell
  // (escape_cells.h; every free cell near it let a path cut a box corner, layout 3 seed 18).
  std::vector<char> around(occupied.size(), 0);
  for (int iy = 0; iy < H; ++iy)
    for (int ix = 0; ix < W; ++ix) {
      const std::size_t i = static_cast<std::size_t>(iy) * W + ix;
      around[i] = out.cells.cells[i] == CellState::kFree &&
                  (grid_.CellCentre(ix, iy) - here).norm() < options_.path_clearance_m;
    }
  const Eigen::Vector2i start = grid_.CellAt(here);
  const auto usable = [&](std::vector<char>& mask, const std::vector<char>& near_mask,
                          const std::vector<char>& blocking, double clearance_m) {
    const std::vector<char> escape = EscapeCells(around, blocking, W, H, start, clearance_m / res);
    mask.assign(occupied.size(), 0);
    for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = !near_mask[i] || escape[i];
  };
  usable(out.safe, near, occupied, options_.path_clearance_m);
  usable(out.safe_from_heard, near_heard, heard, options_.path_clearance_m);
  usable(out.narrow_safe, narrow, occupied, options_.narrow_clearance_m);
  usable(out.narrow_safe_from_heard, narrow_heard, heard, options_.narrow_clearance_m);
  if (options_.squeeze_clearance_m > 0.0)
    usable(out.squeeze_safe_from_heard, squeeze_heard, heard, options_.squeeze_clearance_m);
  if (at_body_clearance) usable(out.body_safe_from_heard, body_heard, heard, body_clearance_m);
  return out;
}

std::optional<std::vector<Eigen::Vector2d>> SonarExplorer::CellPath(
    const std::vector<char>& traversable, const std::vector<char>& goal,
    const Eigen::Vector2d& here) const {
  const int W = grid_.width(), H = grid_.height();
  const Eigen::Vector2i start = grid_.CellAt(here);
  if (start.x() < 0) return std::nullopt;
  const std::vector<Eigen::Vector2i> cells = ShortestCellPath(traversable, goal, W, H, start);
  if (cells.empty()) return std::nullopt;
  const std::vector<Eigen::Vector2i> path = SimplifyPath(cells, traversable, W, H);
  std::vector<Eigen::Vector2d> waypoints;
  for (std::size_t k = 1; k < path.size(); ++k)
    waypoints.push_back(grid_.CellCentre(path[k].x(), path[k].y()));
  return waypoints;
}

bool SonarExplorer::LegsClear(const PlanningCells& planning, const Eigen::Vector2d& here,
                              const std::vector<Eigen::Vector2d>& path) const {
  const double step = grid_.resolution_m() / 4.0;
  Eigen::Vector2d from = here;
  for (const Eigen::Vector2d& to : path) {
    const int n = std::max(1, static_cast<int>(std::ceil((to - from).norm() / step)));
    for (int k = 0; k <= n; ++k) {
      const Eigen::Vector2i c = grid_.CellAt(from + (to - from) * (static_cast<double>(k) / n));
      if (c.x() < 0 || !planning.safe[static_cast<std::size_t>(c.y()) * grid_.width() + c.x()])
        return false;
    }
    from = to;
  }
  return true;
}

std::vector<Eigen::Vector2d> SonarExplorer::SafePathTo(const PlanningCells& planning,
                                                       const CognitiveMap& map,
                                                       const Eigen::Vector2d& here,
                                                       const Eigen::Vector2d& target) const {
  // The seed's x/y moves along the graph when they keep clear of everything heard; otherwise the
  // shortest way over the grid cells that do, inside the room as fitted.
  std::vector<Eigen::Vector2d> path = PlanPath(map.partitions, map.graph, here, target);
  if (!path.empty() && LegsClear(planning, here, path)) return path;
  path = CellPathTo(planning.safe, map.room, here, target);
  if (path.empty()) path = CellPathTo(planning.narrow_safe, map.room, here, target);
  return path;
}

std::vector<Eigen::Vector2d> SonarExplorer::CellPathTo(const std::vector<char>& safe,
                                                       const Rect& room,
                                                       const Eigen::Vector2d& here,
                                                       const Eigen::Vector2d& target) const {
  const int W = grid_.width(), H = grid_.height();
  std::vector<char> traversable(safe.size(), 0), goal(safe.size(), 0);
  for (int iy = 0; iy < H; ++iy)
    for (int ix = 0; ix < W; ++ix) {
      const std::size_t i = static_cast<std::size_t>(iy) * W + ix;
      traversable[i] = safe[i] && room.Contains(grid_.CellCentre(ix, iy));
    }
  const Eigen::Vector2i t = grid_.CellAt(target);
  if (t.x() < 0) return {};
  goal[static_cast<std::size_t>(t.y()) * W + t.x()] = 1;
  std::vector<Eigen::Vector2d> path =
      CellPath(traversable, goal, here).value_or(std::vector<Eigen::Vector2d>{});
  if (!path.empty()) path.back() = target;
  return path;
}

std::optional<std::vector<Eigen::Vector2d>> SonarExplorer::PlanToAnyFrontier(
    const PlanningCells& planning, const Eigen::Vector2d& here) const {
  std::optional<std::vector<Eigen::Vector2d>> path =
      PlanToFrontier(planning, planning.safe_from_heard, here);
  if (!path) path = PlanToFrontier(planning, planning.narrow_safe_from_heard, here);
  if (!path && !planning.squeeze_safe_from_heard.empty())
    path = PlanToFrontier(planning, planning.squeeze_safe_from_heard, here);
  return path;
}

std::optional<std::vector<Eigen::Vector2d>> SonarExplorer::PlanToFrontier(
    const PlanningCells& planning, const std::vector<char>& safe_from_heard,
    const Eigen::Vector2d& here) const {
  const int W = grid_.width(), H = grid_.height();
  const double res = grid_.resolution_m();
  // Unknown cells next to an occupied one are the edge of a wall the sonar has heard, not space
  // still to explore: the frontier is where unknown space lies open.
  CellMap open = planning.cells;
  {
    std::vector<char> heard(open.cells.size(), 0);
    for (std::size_t i = 0; i < heard.size(); ++i) heard[i] = open.cells[i] == CellState::kOccupied;
    const std::vector<char> near = Dilate(heard, W, H, options_.frontier_wall_band_m / res);
    for (std::size_t i = 0; i < near.size(); ++i)
      if (near[i] && open.cells[i] == CellState::kUnknown) open.cells[i] = CellState::kOccupied;
  }
  std::vector<char> pending = FrontierMask(open);
  for (std::size_t i = 0; i < pending.size(); ++i) pending[i] = pending[i] && !looked_[i];
  pending = KeepClusters(pending, W, H, options_.frontier_min_cells);
  // Goals: cells close enough that arriving (within the waypoint tolerance) looks at the frontier.
  const std::vector<char> near_frontier =
      Dilate(pending, W, H, (options_.frontier_view_m - options_.waypoint_tolerance_m) / res);
  std::vector<char> traversable(planning.safe.size(), 0), goal(planning.safe.size(), 0);
  for (int iy = 0; iy < H; ++iy)
    for (int ix = 0; ix < W; ++ix) {
      const std::size_t i = static_cast<std::size_t>(iy) * W + ix;
      traversable[i] = safe_from_heard[i] && planning.cells.cells[i] == CellState::kFree;
      goal[i] = near_frontier[i] && traversable[i] && !Abandoned(grid_.CellCentre(ix, iy));
    }
  return CellPath(traversable, goal, here);
}

Eigen::Vector2d SonarExplorer::ContactPoint(const msgs::Pose2D& X_WR, int panel, int panels) const {
  const double bearing = X_WR.theta_rad + 2.0 * M_PI * panel / panels;
  return Position(X_WR) +
         (options_.robot_radius_m + 0.02) * Eigen::Vector2d(std::cos(bearing), std::sin(bearing));
}

void SonarExplorer::KeepContactAndDropMove(const msgs::Pose2D& X_WR,
                                           const Eigen::Vector2d& contact) {
  contacts_.push_back(contact);
  Note("contact", "", contact);
  last_tier_ = LastTier::kNone;
  if (perimeter_done_ && !path_.empty()) GiveUpMove(Position(X_WR), "bump");
  path_.clear();
  heading_to_frontier_ = false;
  last_replan_s_ = -1e9;
}

bool SonarExplorer::StartWedgeTurn(const robot::ControllerInput& input) {
  if (!options_.bump_wedge_turns || !backing_off_from_ || wedge_heading_rad_ ||
      input.bumpers == nullptr)
    return false;
  // While backing off, or as long again after: the wheels ramp from the back-off into the
  // planner's turn for ~0.5 s, still rolling on (generated world 32 of seed 30: the second corner
  // was touched 0.2-0.3 s after each back-off ended).
  if (input.time_s >= backing_off_until_s_ + options_.bump_back_off_s) {
    backing_off_from_.reset();
    return false;
  }
  const msgs::Pose2D& X_WR = input.X_WR_estimate;
  const Eigen::Vector2d here = Position(X_WR);
  const Eigen::Vector2d first = *backing_off_from_;
  const auto& pressed = input.bumpers->pressed;
  const int n = static_cast<int>(pressed.size());
  for (int panel = 0; panel < n; ++panel) {
    if (!pressed[panel]) continue;
    const Eigen::Vector2d second = ContactPoint(X_WR, panel, n);
    // The same half as the first contact: that contact still pressed as the robot leaves it.
    if ((first - here).dot(second - here) >= 0.0) continue;
    KeepContactAndDropMove(X_WR, second);
    backing_off_until_s_ = -1.0;
    backing_off_from_.reset();
    if (options_.bump_stops_wheels) command_ = {};
    // Along the gap: perpendicular to the line through the two contacts, towards the side of it
    // the robot stands on (it backed off into that side, away from both points).
    const Eigen::Vector2d line = second - first;
    Eigen::Vector2d along_gap(-line.y(), line.x());
    if (along_gap.dot(here - first) < 0.0) along_gap = -along_gap;
    wedge_heading_rad_ = std::atan2(along_gap.y(), along_gap.x());
    // Bounded: when the encoder heading does not come round (a wheel held), the turn is given up
    // after twice its time at turn_rate_rad_s plus one back-off.
    wedge_turn_until_s_ = input.time_s +
                          2.0 * std::abs(msgs::WrapAngle(*wedge_heading_rad_ - X_WR.theta_rad)) /
                              options_.turn_rate_rad_s +
                          options_.bump_back_off_s;
    return true;
  }
  return false;
}

std::optional<msgs::WheelSpeedCommand> SonarExplorer::ReactToBump(
    const robot::ControllerInput& input) {
  const msgs::Pose2D& X_WR = input.X_WR_estimate;
  robot::BodyTwist twist;
  if (StartWedgeTurn(input) || wedge_heading_rad_) {
    // The body is round: the turn on the spot touches nothing, and panels pressed meanwhile are
    // the two contacts it turns between.
    const double error = msgs::WrapAngle(*wedge_heading_rad_ - X_WR.theta_rad);
    if (std::abs(error) > kAlignedRad && input.time_s < wedge_turn_until_s_) {
      twist.angular_rad_s =
          std::clamp(2.0 * error, -options_.turn_rate_rad_s, options_.turn_rate_rad_s);
      return robot::TwistToWheelSpeeds(spec_, twist);
    }
    // Along the gap (or given up): the planner takes over, the two contacts blocking their cells.
    wedge_heading_rad_.reset();
  }
  if (input.time_s < backing_off_until_s_) {
    twist.linear_m_s = backing_off_speed_m_s_;
    return robot::TwistToWheelSpeeds(spec_, twist);
  }
  if (input.bumpers == nullptr) return std::nullopt;
  const auto& pressed = input.bumpers->pressed;
  const int n = static_cast<int>(pressed.size());
  int panel = -1;
  for (int i = 0; i < n && panel < 0; ++i)
    if (pressed[i]) panel = i;
  if (panel < 0) return std::nullopt;
  // The sonar missed something (a corner inside its blanking range, or a face seen at a grazing
  // angle): the contact point is in the way from now on, the move is abandoned, and the robot
  // backs away from the panel that touched.
  KeepContactAndDropMove(X_WR, ContactPoint(X_WR, panel, n));
  // Away from the panel along the robot's axis. A side panel's arc reaches both the front and the
  // rear half, and its centre's cosine is 0 up to rounding (+6e-17 left, -2e-16 right): the
  // contact came from the motion, so the robot backs off against it (backwards when it was not
  // driving). Deciding by the rounding sent it forwards along the face it touched with a right
  // panel, pushing into it for the whole back-off (generated rooms: 1.5 s contacts, +10-12 deg of
  // encoder heading).
  const double along = std::cos(2.0 * M_PI * panel / n);
  const double moving = robot::WheelSpeedsToTwist(spec_, command_).linear_m_s;
  const bool side_panel = std::abs(along) < std::sin(M_PI / n);
  const bool away_is_back = side_panel ? moving >= 0.0 : along >= 0.0;
  backing_off_speed_m_s_ =
      away_is_back ? -options_.bump_back_off_speed_m_s : options_.bump_back_off_speed_m_s;
  backing_off_until_s_ = input.time_s + options_.bump_back_off_s;
  backing_off_from_ = contacts_.back();
  // Stop the wheels at once, as a base's bumper circuit does (Update ramps on from here): ramping
  // down under the limit kept pushing into the obstacle for most of a second, and that slip was
  // the drift.
  if (options_.bump_stops_wheels) command_ = {};
  twist.linear_m_s = backing_off_speed_m_s_;
  return robot::TwistToWheelSpeeds(spec_, twist);
}

bool SonarExplorer::MapBlocksFront(const msgs::Pose2D& X_WR) const {
  // Occupied cells heard earlier in the corridor the body sweeps ahead: a corner the sonar heard
  // from elsewhere stays there when the sonar now misses it (specular, or inside 0.15 m).
  const double reach = options_.stop_range_m + options_.robot_radius_m;
  // Narrower than the echo corridor (cell centres are exact; echoes are off by the cone), and
  // narrower than path_clearance_m, so that a planned path is not blocked by what planned it.
  const double half_width = options_.robot_radius_m + options_.front_margin_m;
  const Eigen::Vector2d here = Position(X_WR);
  const Eigen::Vector2d ahead(std::cos(X_WR.theta_rad), std::sin(X_WR.theta_rad));
  const Eigen::Vector2i c = grid_.CellAt(here);
  if (c.x() < 0) return false;
  const int r = static_cast<int>(std::ceil(std::hypot(reach, half_width) / grid_.resolution_m()));
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const int ix = c.x() + dx, iy = c.y() + dy;
      if (!grid_.Contains(ix, iy) ||
          !HeardForPlanning(ix, iy, last_tier_ == LastTier::kThroughAxisFree))
        continue;
      const Eigen::Vector2d d = grid_.CellCentre(ix, iy) - here;
      const double along = d.dot(ahead);
      const double side = ahead.x() * d.y() - ahead.y() * d.x();
      if (along > 0.0 && along < reach && std::abs(side) < half_width) return true;
    }
  return false;
}

bool SonarExplorer::HeardForPlanning(int ix, int iy, bool through_axis_free) const {
  if (grid_.Probability(ix, iy) <= 1.0 - options_.map.eps) return false;
  const int min_passes = options_.map.beam_free_min_passes;
  return !(through_axis_free && start_ && min_passes > 0 &&
           beam_free_.Passes(ix, iy) >= min_passes);
}

std::optional<std::vector<Eigen::Vector2d>> SonarExplorer::PlanToLastTierFrontier(
    LastTier tier, const CognitiveMap& map, const Eigen::Vector2d& here) {
  const bool through_axis_free = tier == LastTier::kThroughAxisFree;
  const PlanningCells planning =
      Planning(here, map.obstacles, through_axis_free, !through_axis_free);
  // Through the axis-free cells: every clearance tier of the frontier search; at the body's
  // clearance: the cells that far from what was heard.
  const auto plan = [&]() {
    return through_axis_free ? PlanToAnyFrontier(planning, here)
                             : PlanToFrontier(planning, planning.body_safe_from_heard, here);
  };
  std::optional<std::vector<Eigen::Vector2d>> frontier = plan();
  if (frontier && frontier->empty()) {
    // Standing on such a goal already: look from here, as the normal tiers do.
    MarkLooked(here);
    const Eigen::Vector2i cell = grid_.CellAt(here);
    if (cell.x() >= 0) MarkLooked(grid_.CellCentre(cell.x(), cell.y()));
    frontier = plan();
  }
  if (!frontier || frontier->empty()) return std::nullopt;
  Note("goal", through_axis_free ? "frontier_through_axis_free" : "frontier_at_body_clearance",
       frontier->back());
  return frontier;
}

std::optional<double> SonarExplorer::ContactAhead(const msgs::Pose2D& X_WR) const {
  // The corridor of MapBlocksFront: a contact point is exact to the body's radius.
  const double reach = options_.stop_range_m + options_.robot_radius_m;
  const double half_width = options_.robot_radius_m + options_.front_margin_m;
  const Eigen::Vector2d ahead(std::cos(X_WR.theta_rad), std::sin(X_WR.theta_rad));
  std::optional<double> nearest_side;
  double nearest_along = reach;
  for (const Eigen::Vector2d& p : contacts_) {
    const Eigen::Vector2d d = p - Position(X_WR);
    const double along = d.dot(ahead);
    const double side = ahead.x() * d.y() - ahead.y() * d.x();
    if (along > 0.0 && along < nearest_along && std::abs(side) < half_width) {
      nearest_along = along;
      nearest_side = side;
    }
  }
  return nearest_side;
}

msgs::WheelSpeedCommand SonarExplorer::Explore(const robot::ControllerInput& input) {
  const msgs::Pose2D& X_WR = input.X_WR_estimate;
  if (!explore_start_s_) explore_start_s_ = input.time_s;
  if (input.time_s - *explore_start_s_ > options_.explore_max_s) {
    Finish("time_limit", input.time_s);
    return {};
  }
  if (input.time_s - last_replan_s_ >= options_.replan_period_s || path_.empty()) {
    last_replan_s_ = input.time_s;
    Replan(X_WR, input.time_s);
    if (finished_ || path_.empty()) return {};
  }
  while (!path_.empty() && (path_.front() - Position(X_WR)).norm() < options_.waypoint_tolerance_m)
    path_.erase(path_.begin());
  if (path_.empty()) {
    // Arrived at a frontier: what the sonar could see of it from here is seen; passing by does not
    // count, since the ring may have heard nothing of it on the way.
    if (heading_to_frontier_) MarkLooked(Position(X_WR));
    heading_to_frontier_ = false;
    last_tier_ = LastTier::kNone;
    return {};
  }
  msgs::WheelSpeedCommand command = DriveTo(X_WR, path_.front());
  const robot::BodyTwist twist = robot::WheelSpeedsToTwist(spec_, command);
  const std::optional<Eigen::Vector2d> echo =
      twist.linear_m_s > 0.0 && input.sonar != nullptr ? FrontBlocked(*input.sonar) : std::nullopt;
  if (echo) {
    // The planner did not know this echo: it is in the way from now on.
    const double c = std::cos(X_WR.theta_rad), s = std::sin(X_WR.theta_rad);
    blocking_echoes_.push_back(Position(X_WR) + Eigen::Vector2d(c * echo->x() - s * echo->y(),
                                                                s * echo->x() + c * echo->y()));
  }
  if (twist.linear_m_s > 0.0 && (echo || MapBlocksFront(X_WR))) {
    // Negative experience: this move cannot be made; forget the path and replan at once.
    GiveUpMove(Position(X_WR), echo ? "front_echo" : "map");
    path_.clear();
    last_replan_s_ = -1e9;
    return {};
  }
  return command;
}

msgs::WheelSpeedCommand SonarExplorer::Update(const robot::ControllerInput& input) {
  // A NaN would go into the grid's origin, the planner's cells and every time test for good.
  if (!std::isfinite(input.time_s))
    throw std::invalid_argument("time_s: must be finite, got " +
                                msgs::ShortestNumber(input.time_s));
  RequireFinitePose("X_WR_estimate", input.X_WR_estimate);
  now_s_ = input.time_s;
  here_ = Position(input.X_WR_estimate);
  const msgs::WheelSpeedCommand wanted = finished_ ? msgs::WheelSpeedCommand{} : Decide(input);
  // Wheel speeds change at most max_wheel_accel_rad_s2: a step in speed makes the tyres slip on
  // the floor, which the encoders do not see (it was most of the heading drift).
  // A tick whose time repeats or steps back (a driver's clock) changes no wheel speed.
  const double dt = last_command_s_ < 0.0 ? 0.0 : std::max(input.time_s - last_command_s_, 0.0);
  last_command_s_ = input.time_s;
  const double step = options_.max_wheel_accel_rad_s2 * dt;
  command_.left_rad_s += std::clamp(wanted.left_rad_s - command_.left_rad_s, -step, step);
  command_.right_rad_s += std::clamp(wanted.right_rad_s - command_.right_rad_s, -step, step);
  return command_;
}

msgs::WheelSpeedCommand SonarExplorer::Decide(const robot::ControllerInput& input) {
  const msgs::Pose2D& X_WR = input.X_WR_estimate;
  if (!start_) {
    start_ = X_WR;
    LogOddsGridOptions g;
    g.resolution_m = options_.grid_resolution_m;
    const int cells =
        static_cast<int>(std::ceil(2.0 * options_.grid_half_extent_m / options_.grid_resolution_m));
    g.width = g.height = cells;
    g.origin_xy = Position(X_WR) - Eigen::Vector2d::Constant(options_.grid_half_extent_m);
    g.log_odds.p_min = options_.p_min;
    g.log_odds.log_odds_limit = options_.log_odds_limit;
    grid_ = LogOddsGrid(g);
    beam_free_ = BeamFreeGrid(g, options_.beam_free);
    visits_.assign(static_cast<std::size_t>(cells) * cells, 0.0);
    visited_.assign(visits_.size(), 0);
    looked_.assign(visits_.size(), 0);
  }
  if (input.sonar != nullptr && input.sonar->time_s > last_ring_time_s_) {
    last_ring_time_s_ = input.sonar->time_s;
    grid_.Integrate(*model_, *input.sonar, X_WR);
    beam_free_.Integrate(*input.sonar, X_WR);
    ++rings_integrated_;
  }
  if (const std::optional<msgs::WheelSpeedCommand> back = ReactToBump(input)) return *back;
  // Cells within visit_radius_m of the robot count as visited.
  const Eigen::Vector2i c = grid_.CellAt(Position(X_WR));
  if (c.x() >= 0) {
    const int r = static_cast<int>(std::ceil(options_.visit_radius_m / grid_.resolution_m()));
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        const int ix = c.x() + dx, iy = c.y() + dy;
        if (grid_.Contains(ix, iy) &&
            (grid_.CellCentre(ix, iy) - Position(X_WR)).norm() <= options_.visit_radius_m)
          visited_[iy * grid_.width() + ix] = 1;
      }
  }
  if (!perimeter_done_) {
    if (!perimeter_start_s_) perimeter_start_s_ = input.time_s;
    if (!spot_ || (Position(X_WR) - *spot_).norm() > options_.robot_radius_m) {
      spot_ = Position(X_WR);
      spot_turned_rad_ = 0.0;
    } else if (last_theta_) {
      spot_turned_rad_ += std::abs(msgs::WrapAngle(X_WR.theta_rad - *last_theta_));
    }
    if (last_theta_ && follower_->wall())
      turned_rad_ += msgs::WrapAngle(X_WR.theta_rad - *last_theta_);
    last_theta_ = X_WR.theta_rad;
    if (last_position_ && follower_->wall())
      perimeter_travelled_m_ += (Position(X_WR) - *last_position_).norm();
    last_position_ = Position(X_WR);
    const bool closed = std::abs(turned_rad_) >= options_.perimeter_turn_rad &&
                        perimeter_travelled_m_ >= options_.perimeter_min_m;
    const bool timed_out = input.time_s - *perimeter_start_s_ > options_.perimeter_max_s;
    if (closed || timed_out || spot_turned_rad_ >= options_.perimeter_stuck_turn_rad) {
      perimeter_done_ = true;
      Note("perimeter_end", closed ? "closed" : (timed_out ? "time_limit" : "stuck"),
           Position(X_WR));
    } else {
      // The follower cannot hear an obstacle corner met head-on; a close front echo turns the
      // robot on the spot away from the wall (on its left) until the way ahead is clear, and a
      // point touched before away from that point.
      const msgs::WheelSpeedCommand command = follower_->Update(input);
      if (robot::WheelSpeedsToTwist(spec_, command).linear_m_s > 0.0) {
        robot::BodyTwist turn;
        turn.angular_rad_s = -options_.turn_rate_rad_s;
        if ((input.sonar != nullptr && FrontBlocked(*input.sonar).has_value()) ||
            MapBlocksFront(X_WR))
          return robot::TwistToWheelSpeeds(spec_, turn);
        if (options_.perimeter_avoids_contacts) {
          if (const std::optional<double> side = ContactAhead(X_WR)) {
            if (*side < 0.0) turn.angular_rad_s = options_.turn_rate_rad_s;
            return robot::TwistToWheelSpeeds(spec_, turn);
          }
        }
      }
      return command;
    }
  }
  return Explore(input);
}

}  // namespace plywood::perception
