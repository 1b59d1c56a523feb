#pragma once

#include <Eigen/Core>
#include <string>

namespace plywood::perception {

// One decision of the sonar explorer, kept so that a run's course can be read back (why it went
// where it did, why it ended): exploration_log.csv of a seed 001 run.
//   perimeter_end: the boundary phase is over; detail "closed" (turned once round, far enough),
//                  "time_limit" (perimeter_max_s) or "stuck" (turned on the spot); at: the robot.
//   goal:          a new goal; detail "circuit_corner", "place", "frontier" or
//                  "frontier_through_axis_free" (the last tier, last_frontier_through_axis_free),
//                  "frontier_at_body_clearance" (the last tier, last_frontier_at_body_clearance);
//                  at: the goal.
//   given_up:      a move given up; detail "front_echo", "map" (heard cells ahead) or "bump";
//                  at: where the robot was.
//   contact:       a bump panel pressed; at: the point it touched.
//   finish:        exploration ended; detail the end reason; at: the robot.
struct ExplorationEvent {
  double time_s = 0.0;
  std::string kind;
  std::string detail;
  Eigen::Vector2d at{0.0, 0.0};  // odometry frame
};

}  // namespace plywood::perception
