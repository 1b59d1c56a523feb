#include "perception/sonar_explorer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "robot/diff_drive_kinematics.h"

namespace plywood::perception {
namespace {

void RequirePositive(const std::string& field, double v) {
  if (!(std::isfinite(v) && v > 0.0))
    throw std::invalid_argument(field + ": must be a finite number > 0, got " + std::to_string(v));
}

void RequireNonNegative(const std::string& field, double v) {
  if (!(std::isfinite(v) && v >= 0.0))
    throw std::invalid_argument(field + ": must be a finite number >= 0, got " + std::to_string(v));
}

Eigen::Vector2d Position(const msgs::Pose2D& X) { return {X.x_m, X.y_m}; }

}  // namespace

void SonarExplorerOptions::Validate() const {
  if (sonar_model != "net" && sonar_model != "classical")
    throw std::invalid_argument("sonar_model: must be net or classical, got '" + sonar_model + "'");
  if (sonar_model == "net" && weights_file.empty())
    throw std::invalid_argument("weights_file: needed when sonar_model is net");
  RequirePositive("grid_half_extent_m", grid_half_extent_m);
  RequirePositive("grid_resolution_m", grid_resolution_m);
  if (!(p_min > 0.0 && p_min < 0.5)) throw std::invalid_argument("p_min: must be in (0, 0.5)");
  RequirePositive("log_odds_limit", log_odds_limit);
  map.Validate();
  RequirePositive("wall_distance_m", wall_distance_m);
  RequirePositive("perimeter_turn_rad", perimeter_turn_rad);
  RequirePositive("perimeter_max_s", perimeter_max_s);
  RequirePositive("speed_m_s", speed_m_s);
  RequirePositive("turn_rate_rad_s", turn_rate_rad_s);
  RequirePositive("replan_period_s", replan_period_s);
  if (!(visit_decay > 0.0 && visit_decay <= 1.0))
    throw std::invalid_argument("visit_decay: must be in (0, 1]");
  RequirePositive("unvisited_utility", unvisited_utility);
  RequirePositive("visit_radius_m", visit_radius_m);
  RequirePositive("place_size_m", place_size_m);
  RequireNonNegative("perimeter_min_m", perimeter_min_m);
  RequirePositive("clearance_m", clearance_m);
  RequirePositive("stop_range_m", stop_range_m);
  RequirePositive("waypoint_tolerance_m", waypoint_tolerance_m);
  RequirePositive("explore_max_s", explore_max_s);
}

SonarExplorer::SonarExplorer(const robot::DiffDriveSpec& spec, const SonarExplorerOptions& options,
                             std::shared_ptr<const SonarCellModel> model)
    : spec_(spec), options_(options), model_(std::move(model)) {
  spec_.Validate();
  options_.Validate();
  if (!model_) throw std::invalid_argument("sonar_model: no model given");
  robot::WallFollowingOptions follow;
  follow.side = robot::WallSide::kLeft;
  follow.distance_m = options_.wall_distance_m;
  follow.speed_m_s = options_.speed_m_s;
  follower_ = std::make_unique<robot::WallFollowingController>(spec_, follow);
}

CognitiveMap SonarExplorer::Map() const {
  const Eigen::Vector2d inside =
      start_ ? Position(*start_) : grid_.CellCentre(grid_.width() / 2, grid_.height() / 2);
  CognitiveMap map = BuildCognitiveMap(grid_, inside, options_.map);
  // Failed moves: the transition between the partitions at either end goes into D.
  for (const auto& [from, to] : failed_moves_) {
    const int a = map.partitions.Find(from), b = map.partitions.Find(to);
    if (a >= 0 && b >= 0 && a != b) map.negative.Forbid(a, b);
  }
  map.graph = BuildGraph(map.partitions, map.adjacency, map.negative);
  return map;
}

bool SonarExplorer::FrontBlocked(const msgs::RangeRing& ring) const {
  // The echo points in the corridor the robot body sweeps ahead. The sonars up to 60 deg off the
  // axis count, since an obstacle corner met at an angle is heard only by the oblique ones.
  constexpr double kRadius = 0.2;      // the Magellan's radius
  constexpr double kSideMargin = 0.1;  // corridor half-width = radius + this
  for (const auto& r : ring.readings) {
    const double bearing = msgs::WrapAngle(r.X_RS.theta_rad);
    if (!r.echo || std::abs(bearing) > 1.05) continue;
    const double along = r.X_RS.x_m + r.range_m * std::cos(bearing);
    const double side = r.X_RS.y_m + r.range_m * std::sin(bearing);
    if (along > 0.0 && along < options_.stop_range_m + kRadius &&
        std::abs(side) < kRadius + kSideMargin)
      return true;
  }
  return false;
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
  if (std::abs(heading_error) < 0.2)
    twist.linear_m_s = std::min(options_.speed_m_s, 0.1 + d.norm());
  return robot::TwistToWheelSpeeds(spec_, twist);
}

void SonarExplorer::Replan(const msgs::Pose2D& X_WR) {
  CognitiveMap map = Map();
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
  for (double& c : visits_) c *= options_.visit_decay;
  const Eigen::Vector2i cell = grid_.CellAt(here);
  if (cell.x() >= 0) visits_[cell.y() * grid_.width() + cell.x()] += 1.0;
  const auto& parts = map.partitions.partitions();
  double best_u = -1.0, best_d = std::numeric_limits<double>::infinity();
  int best = -1;
  bool all_visited = true;
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
    if (!clear || map.partitions.Find(t) < 0) continue;
    const Eigen::Vector2i tc = grid_.CellAt(t);
    if (tc.x() < 0) continue;
    if (!visited_[tc.y() * grid_.width() + tc.x()]) all_visited = false;
    double c = 0.0;
    for (int iy = 0; iy < grid_.height(); ++iy)
      for (int ix = 0; ix < grid_.width(); ++ix)
        if (visits_[iy * grid_.width() + ix] > 0.0 && r.Contains(grid_.CellCentre(ix, iy)))
          c += visits_[iy * grid_.width() + ix];
    const double u = c > 0.0 ? 1.0 / c : options_.unvisited_utility;
    const double dist = std::abs(t.x() - here.x()) + std::abs(t.y() - here.y());
    if (dist < options_.visit_radius_m) continue;  // already here
    if (u > best_u + 1e-12 || (std::abs(u - best_u) <= 1e-12 && dist < best_d)) {
      const std::vector<Eigen::Vector2d> path = PlanPath(map.partitions, map.graph, here, t);
      if (path.empty()) continue;
      best_u = u;
      best_d = dist;
      best = node;
      path_ = path;
    }
  }
  target_partition_ = best;
  if (best < 0) path_.clear();
  if (all_visited && best_u < options_.unvisited_utility) finished_ = true;
}

msgs::WheelSpeedCommand SonarExplorer::Explore(const robot::ControllerInput& input) {
  const msgs::Pose2D& X_WR = input.X_WR_estimate;
  if (!explore_start_s_) explore_start_s_ = input.time_s;
  if (input.time_s - *explore_start_s_ > options_.explore_max_s) {
    finished_ = true;
    return {};
  }
  if (input.time_s - last_replan_s_ >= options_.replan_period_s || path_.empty()) {
    last_replan_s_ = input.time_s;
    Replan(X_WR);
    if (finished_ || path_.empty()) return {};
  }
  while (!path_.empty() && (path_.front() - Position(X_WR)).norm() < options_.waypoint_tolerance_m)
    path_.erase(path_.begin());
  if (path_.empty()) return {};
  msgs::WheelSpeedCommand command = DriveTo(X_WR, path_.front());
  const robot::BodyTwist twist = robot::WheelSpeedsToTwist(spec_, command);
  if (twist.linear_m_s > 0.0 && input.sonar != nullptr && FrontBlocked(*input.sonar)) {
    // Negative experience: this move cannot be made; forget the path and replan at once.
    failed_moves_.emplace_back(Position(X_WR), path_.front());
    path_.clear();
    last_replan_s_ = -1e9;
    return {};
  }
  return command;
}

msgs::WheelSpeedCommand SonarExplorer::Update(const robot::ControllerInput& input) {
  if (finished_) return {};
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
    visits_.assign(static_cast<std::size_t>(cells) * cells, 0.0);
    visited_.assign(visits_.size(), 0);
  }
  if (input.sonar != nullptr && input.sonar->time_s > last_ring_time_s_) {
    last_ring_time_s_ = input.sonar->time_s;
    grid_.Integrate(*model_, *input.sonar, X_WR);
    ++rings_integrated_;
  }
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
    if (last_theta_ && follower_->wall())
      turned_rad_ += msgs::WrapAngle(X_WR.theta_rad - *last_theta_);
    last_theta_ = X_WR.theta_rad;
    if (last_position_ && follower_->wall())
      perimeter_travelled_m_ += (Position(X_WR) - *last_position_).norm();
    last_position_ = Position(X_WR);
    if ((std::abs(turned_rad_) >= options_.perimeter_turn_rad &&
         perimeter_travelled_m_ >= options_.perimeter_min_m) ||
        input.time_s - *perimeter_start_s_ > options_.perimeter_max_s) {
      perimeter_done_ = true;
    } else {
      // The follower cannot hear an obstacle corner met head-on; a close front echo turns the
      // robot on the spot away from the wall (on its left) until the way ahead is clear.
      const msgs::WheelSpeedCommand command = follower_->Update(input);
      if (input.sonar != nullptr && robot::WheelSpeedsToTwist(spec_, command).linear_m_s > 0.0 &&
          FrontBlocked(*input.sonar)) {
        robot::BodyTwist turn;
        turn.angular_rad_s = -options_.turn_rate_rad_s;
        return robot::TwistToWheelSpeeds(spec_, turn);
      }
      return command;
    }
  }
  return Explore(input);
}

}  // namespace plywood::perception
