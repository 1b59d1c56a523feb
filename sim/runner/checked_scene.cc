#include "sim/runner/checked_scene.h"

#include <utility>

#include "msgs/angle_units.h"
#include "robot/drive/diff_drive_spec.h"
#include "sim/config/config_error.h"
#include "sim/config/robot_catalog.h"
#include "sim/runner/spawn_refused.h"
#include "sim/world/physical_deviation.h"
#include "sim/world/setup_checks.h"

namespace plywood::sim {

std::unique_ptr<Scene> MakeCheckedScene(const ExperimentConfig& config) {
  const RobotCatalogEntry& robot_entry = FindRobot(config.robot);
  SceneOptions scene_options;
  scene_options.world_mjcf = config.world_path;
  scene_options.robot_mjcf = robot_entry.mjcf;
  scene_options.spawn = {config.spawn.x_m, config.spawn.y_m, config.spawn.theta_deg * kDegToRad};
  scene_options.timestep_s = config.physics.timestep_s;
  scene_options.drive = config.physics.drive;
  auto scene = std::make_unique<Scene>(scene_options);

  // The as-built drive: the model's own wheels, deviated by E_d and E_b.
  if (config.deviation.wheel_diameter_ratio != 1.0 || config.deviation.track_ratio != 1.0) {
    const WheelGeometry built = scene->wheel_geometry();
    robot::DiffDriveSpec as_modelled = robot_entry.nominal;
    as_modelled.wheel_radius_m = (built.left_radius_m + built.right_radius_m) / 2.0;
    as_modelled.track_m = built.track_m;
    scene->SetWheelGeometry(DeviatedWheelGeometry(as_modelled, config.deviation));
  }

  // A scene that cannot give meaningful results is refused before anything runs.
  for (const auto& check :
       {WorldGeomInTheRobotsGroup, WorldGeomTheRobotPassesThrough, MissingFloor,
        PlaneThatIsNotTheFloor, MovableWorldGeometry, WorldGeomNoSensorSees,
        WorldGeomThatChangesTheRobotsContacts, NonDefaultPhysicsOptions, ShrunkContactLists}) {
    if (const auto problem = check(*scene)) {
      throw ConfigError(config.source_file, "world", config.world_path.string() + ": " + *problem);
    }
  }
  for (const auto& [check, advice] :
       {std::pair{&SpawnOutsideWorld, ""}, std::pair{&SpawnCollision, "; choose a free spawn"}}) {
    if (const auto problem = check(*scene)) {
      throw SpawnRefused(config.source_file, *problem, advice,
                         config.world_path.filename().string());
    }
  }
  return scene;
}

}  // namespace plywood::sim
