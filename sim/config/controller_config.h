#pragma once

#include <yaml-cpp/yaml.h>

#include <memory>
#include <string>
#include <vector>

#include "perception/sonar_map/sonar_explorer.h"
#include "robot/control/controller.h"
#include "robot/control/square_path_controller.h"
#include "robot/control/wall_following_controller.h"
#include "robot/control/waypoint_controller.h"
#include "robot/control/wheel_script_controller.h"
#include "robot/drive/diff_drive_spec.h"
#include "robot/plugins/parameter_map.h"

namespace plywood::sim {

class YamlFields;

// Which controller drives the robot, how often it runs, and which pose it steers by. In YAML the
// chosen controller's options sit beside `type`:
//   controller: {type: square_path, side_m: 4, direction: ccw, steer_by: encoder}
// A registered controller's options sit there too (docs/plugins.md).
struct ControllerConfig {
  // idle | square_path | waypoints | wheel_script | wall_following | sonar_explorer, or the name
  // of a registered controller
  std::string type = "idle";
  double rate_hz = 50.0;
  // ground_truth (an ideal localiser) or the name of an odometry estimator the experiment runs
  // (e.g. encoder: what a real robot without a localiser has).
  std::string steer_by = "ground_truth";
  robot::SquarePathOptions square_path;
  robot::WaypointOptions waypoints;
  robot::WheelScriptOptions wheel_script;
  robot::WallFollowingOptions wall_following;
  perception::SonarExplorerOptions sonar_explorer;  // seed 001 (docs/sonar_map.md)
  robot::ParameterMap registered;                   // a registered controller's options
};

// Reads the section; `nominal` is the robot's drive, with which a registered controller is built
// once to check its options. @throws ConfigError naming the field.
void ReadControllerConfig(YamlFields fields, const robot::DiffDriveSpec& nominal,
                          ControllerConfig& config);
YAML::Node WriteControllerConfig(ControllerConfig& config);

// The controller `config` names (built in or registered, sim/config/plugin_loader.h), or nullptr
// for "idle" (the robot stands still).
// @throws std::invalid_argument "<field>: <what is wrong>" for options found bad only when built.
std::unique_ptr<robot::Controller> MakeController(const ControllerConfig& config,
                                                  const robot::DiffDriveSpec& nominal);

// "idle", "square_path", ...: the types that are not registered.
const std::vector<std::string>& BuiltInControllerTypes();

}  // namespace plywood::sim
