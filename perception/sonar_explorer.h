#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "perception/cognitive_map.h"
#include "perception/log_odds_grid.h"
#include "perception/sonar_cell_model.h"
#include "perception/sonar_net.h"
#include "robot/controller.h"
#include "robot/diff_drive_spec.h"
#include "robot/wall_following_controller.h"

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
  CognitiveMapOptions map;
  // Obstacle (and wall) perimeter following first: one full turn of the boundary.
  double wall_distance_m = 0.5;     // 0.45 grazed obstacle corners (layout 3)
  double perimeter_turn_rad = 6.0;  // heading change that closes the circuit (2 pi minus slack)
  double perimeter_max_s = 150.0;
  // Then the seed's utility loop over the partitions.
  double speed_m_s = 0.2;
  double turn_rate_rad_s = 0.8;
  double replan_period_s = 2.0;
  double visit_decay = 0.95;         // lambda: c(p) <- lambda c(p) at every replan
  double unvisited_utility = 100.0;  // K: U(p) of a partition never visited
  double place_size_m = 0.9;         // free partitions are visited as places no larger than this
  double perimeter_min_m = 5.0;      // and at least this far along the boundary
  double visit_radius_m = 0.4;       // being this close to a partition's target counts as a visit
  double clearance_m = 0.4;          // targets keep this far from room walls and obstacles
  double stop_range_m = 0.3;         // a front echo closer than this aborts the move (into D)
  double waypoint_tolerance_m = 0.08;
  double explore_max_s = 200.0;  // then the run is over even if partitions remain unvisited
  // @throws std::invalid_argument naming the field.
  void Validate() const;
};

// Seed 001's exploration controller. It owns the cognitive map: every new sonar ring goes through
// the sonar model into the log-odds grid at the current odometry pose. It first follows the room's
// boundary (wall on the left) for one circuit, then repeatedly rebuilds the partition map, decays
// the visit counts (c <- lambda c), counts a visit to the partition it is in, and drives to the
// free partition with the highest utility U = 1/c (K if never visited) along the graph's shortest
// x/y path. A move that a close front echo blocks puts the transition it was making into D. It
// finishes once every free partition was visited, or after explore_max_s.
class SonarExplorer final : public robot::Controller {
 public:
  // @throws std::invalid_argument for invalid options.
  SonarExplorer(const robot::DiffDriveSpec& spec, const SonarExplorerOptions& options,
                std::shared_ptr<const SonarCellModel> model);

  msgs::WheelSpeedCommand Update(const robot::ControllerInput& input) override;
  bool Finished() const override { return finished_; }

  const LogOddsGrid& grid() const { return grid_; }
  // The map abstracted from the grid now (plus the failed moves in D).
  CognitiveMap Map() const;
  const std::optional<msgs::Pose2D>& start() const { return start_; }
  int rings_integrated() const { return rings_integrated_; }

 private:
  msgs::WheelSpeedCommand Explore(const robot::ControllerInput& input);
  msgs::WheelSpeedCommand DriveTo(const msgs::Pose2D& X_WR, const Eigen::Vector2d& target);
  bool FrontBlocked(const msgs::RangeRing& ring) const;
  void Replan(const msgs::Pose2D& X_WR);

  robot::DiffDriveSpec spec_;
  SonarExplorerOptions options_;
  std::shared_ptr<const SonarCellModel> model_;
  LogOddsGrid grid_;
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
  std::optional<double> explore_start_s_;
  // Visit counts live on the grid's cells so they survive re-partitioning.
  std::vector<double> visits_;
  std::vector<char> visited_;
  double last_replan_s_ = -1e9;
  std::vector<Eigen::Vector2d> path_;
  int target_partition_ = -1;
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> failed_moves_;  // from, to points
  bool finished_ = false;
};

}  // namespace plywood::perception
