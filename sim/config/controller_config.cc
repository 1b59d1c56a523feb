#include "sim/config/controller_config.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <string_view>

#include "sim/config/config_archive.h"
#include "sim/config/config_fields.h"
#include "sim/config/robot_catalog.h"
#include "sim/config/sonar_explorer_fields.h"
#include "sim/config/yaml_fields.h"

namespace plywood::sim {
namespace {

constexpr std::array<std::string_view, 6> kControllerTypes{
    "idle", "square_path", "waypoints", "wheel_script", "wall_following", "sonar_explorer"};

// Reads the shared keys and the chosen controller's options from one mapping.
template <typename Archive>
void VisitChosen(Archive& archive, ControllerConfig& config) {
  archive("rate_hz", config.rate_hz);
  archive("steer_by", config.steer_by);
  if (config.type == "square_path") VisitFields(archive, config.square_path);
  if (config.type == "waypoints") VisitFields(archive, config.waypoints);
  if (config.type == "wheel_script") VisitFields(archive, config.wheel_script);
  if (config.type == "wall_following") VisitFields(archive, config.wall_following);
  if (config.type == "sonar_explorer") VisitFields(archive, config.sonar_explorer);
}

}  // namespace

void ReadControllerConfig(YamlFields fields, ControllerConfig& config) {
  fields.Get("type", &config.type);
  if (std::find(kControllerTypes.begin(), kControllerTypes.end(), config.type) ==
      kControllerTypes.end()) {
    std::string known;
    for (std::string_view type : kControllerTypes)
      known += (known.empty() ? "" : ", ") + std::string(type);
    fields.Fail("type", "unknown controller '" + config.type + "' (known: " + known + ")");
  }
  YamlReadArchive archive(fields);
  VisitChosen(archive, config);
  archive.fields().Finish();
  if (!(config.rate_hz > 0.0)) fields.Fail("rate_hz", "must be a finite number > 0");
  if (config.type == "square_path") fields.Validate(config.square_path);
  if (config.type == "waypoints") fields.Validate(config.waypoints);
  if (config.type == "wheel_script") fields.Validate(config.wheel_script);
  if (config.type == "wall_following") fields.Validate(config.wall_following);
  if (config.type == "sonar_explorer") fields.Validate(config.sonar_explorer);
}

YAML::Node WriteControllerConfig(ControllerConfig& config) {
  YamlWriteArchive archive;
  archive("type", config.type);
  VisitChosen(archive, config);
  return archive.node();
}

std::unique_ptr<robot::Controller> MakeController(const ControllerConfig& config,
                                                  const robot::DiffDriveSpec& nominal) {
  if (config.type == "square_path") {
    return std::make_unique<robot::SquarePathController>(nominal, config.square_path);
  }
  if (config.type == "waypoints") {
    return std::make_unique<robot::WaypointController>(nominal, config.waypoints);
  }
  if (config.type == "wheel_script") {
    return std::make_unique<robot::WheelScriptController>(nominal, config.wheel_script);
  }
  if (config.type == "wall_following") {
    return std::make_unique<robot::WallFollowingController>(nominal, config.wall_following);
  }
  if (config.type == "sonar_explorer") {
    const perception::SonarExplorerOptions& o = config.sonar_explorer;
    std::shared_ptr<const perception::SonarCellModel> model;
    if (o.sonar_model == "net") {
      std::filesystem::path weights = o.weights_file;
      if (weights.is_relative()) weights = DataRoot() / weights;
      try {
        model = std::make_shared<perception::SonarNet>(perception::SonarNet::Load(weights));
      } catch (const std::runtime_error& e) {
        // Bad input like any other option: the runner names the experiment file with it.
        throw std::invalid_argument(std::string("weights_file: ") + e.what());
      }
    } else {
      model = std::make_shared<perception::ClassicalSonarModel>();
    }
    return std::make_unique<perception::SonarExplorer>(nominal, o, model);
  }
  return nullptr;
}

}  // namespace plywood::sim
