#include "sim/runner/controller_targets.h"

#include <cmath>

#include "msgs/shortest_number.h"
#include "robot/control/square_path_controller.h"
#include "sim/config/config_error.h"
#include "sim/config/robot_catalog.h"
#include "sim/runner/format_number.h"
#include "sim/world/setup_checks.h"

namespace plywood::sim {

std::optional<ControllerTargetProblem> FindControllerTargetProblem(const ExperimentConfig& config,
                                                                   const Scene& scene) {
  const std::string world_name = config.world_path.filename().string();
  // A waypoint inside a wall, a box or a table leg (s51) or beyond the world's walls (s52) is
  // never reached: the robot pushed against a wall to the end of the run, exit 0, with the
  // figures of that.
  const auto unreachable = [&](double x_m, double y_m) -> std::optional<std::string> {
    if (auto problem = PointOutsideWorld(scene, x_m, y_m)) return problem;
    return PointInsideWorldGeom(scene, x_m, y_m);
  };
  if (config.controller.type == "waypoints") {
    const auto& points = config.controller.waypoints.waypoints;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (const auto problem = unreachable(points[i].x_m, points[i].y_m)) {
        return ControllerTargetProblem{
            "controller.waypoints[" + std::to_string(i) + "]",
            *problem + " in " + world_name +
                ": the robot can never reach it; move the waypoint into free space",
            {"controller.waypoints", "world"}};
      }
    }
    // A tolerance that takes in every waypoint from the spawn passes them all on the first tick:
    // reach_tolerance_m 1e300 gave controller_finished 1 with 0 m driven, exit 0 (s55); with
    // loop: true the robot chased whichever waypoint each tick's count stopped on.
    const msgs::Pose2D spawn = scene.TruePose();
    double farthest_m = 0.0;
    std::size_t farthest = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double d_m = std::hypot(points[i].x_m - spawn.x_m, points[i].y_m - spawn.y_m);
      if (d_m > farthest_m) {
        farthest_m = d_m;
        farthest = i;
      }
    }
    const double tolerance_m = config.controller.waypoints.reach_tolerance_m;
    if (!points.empty() && farthest_m <= tolerance_m) {
      return ControllerTargetProblem{
          "controller.reach_tolerance_m",
          msgs::ShortestNumber(tolerance_m) +
              " m takes in every waypoint from the spawn (the farthest, waypoints[" +
              std::to_string(farthest) + "], lies " + msgs::SixDigitNumber(farthest_m) +
              " m from it): each counts as reached on the first tick, before the robot drives to "
              "any; give a tolerance below that distance",
          {"controller.reach_tolerance_m", "controller.waypoints", "robot.spawn"}};
    }
  }
  // A square's corners are its waypoints: square_hall.yaml with side_m 20 drove the P3-DX into the
  // hall's east wall, encoder drift 82 %, controller_finished 0, exit 0 (s52). The controller lays
  // them out from the spawn (its first estimate), corner 0 the spawn itself. The UMBmark protocol
  // turns the spawn for its clockwise runs and walks its squares itself (s46).
  if (config.controller.type == "square_path" && config.protocol == "single") {
    const robot::SquarePathOptions& square = config.controller.square_path;
    const std::vector<msgs::Pose2D> corners = robot::SquareCorners(scene.TruePose(), square);
    for (int k = 1; k < 4; ++k) {
      if (const auto problem = unreachable(corners[k].x_m, corners[k].y_m)) {
        return ControllerTargetProblem{
            "controller.side_m",
            "the " + FormatNumber(square.side_m) + " m " +
                std::string(robot::ToString(square.direction)) +
                " square from the spawn: its corner " + std::to_string(k) + " " + *problem +
                " in " + world_name +
                ": the robot can never reach it; shorten side_m or move robot.spawn",
            {"controller.side_m", "controller.direction", "robot.spawn", "world"}};
      }
    }
  }
  // Controllers plan with robot.nominal's wheel speed limit; motors that clamp below it would drive
  // other speeds than commanded without a word (audit s47: 20 rad/s against the P3-DX's 12.3).
  if (const double motors = scene.WheelMotorLimitRadS();
      config.nominal.max_wheel_speed_rad_s > motors) {
    return ControllerTargetProblem{"robot.nominal.max_wheel_speed_rad_s",
                                   FormatNumber(config.nominal.max_wheel_speed_rad_s) +
                                       " rad/s is more than the wheel motors take (ctrlrange +-" +
                                       FormatNumber(motors) + " rad/s in " +
                                       FindRobot(config.robot).mjcf.filename().string() +
                                       "): they would clamp the controller's commands",
                                   {"robot.nominal.max_wheel_speed_rad_s", "robot.model"}};
  }
  return std::nullopt;
}

void RequireReachableControllerTargets(const ExperimentConfig& config, const Scene& scene) {
  if (const auto problem = FindControllerTargetProblem(config, scene)) {
    throw ConfigError(config.source_file, problem->field, problem->message);
  }
}

}  // namespace plywood::sim
