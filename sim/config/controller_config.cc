#include "sim/config/controller_config.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <utility>
#include <vector>

#include "robot/control/controller.h"
#include "sim/config/config_archive.h"
#include "sim/config/config_fields.h"
#include "sim/config/guarded_algorithms.h"
#include "sim/config/plugin_loader.h"
#include "sim/config/plugin_options.h"
#include "sim/config/robot_catalog.h"
#include "sim/config/sonar_explorer_fields.h"
#include "sim/config/yaml_fields.h"

namespace plywood::sim {
namespace {

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

const std::vector<std::string>& BuiltInControllerTypes() {
  static const std::vector<std::string> types{"idle",         "square_path",    "waypoints",
                                              "wheel_script", "wall_following", "sonar_explorer"};
  return types;
}

namespace {

// The forward speeds must be ones the robot's wheels can drive (beyond them the wheel limits cap
// the speed without a word): checked against the experiment's nominal spec as the file is read,
// so the line names the field before anything runs (the controllers check it again).
void RequireDrivableSpeeds(const YamlFields& fields, const robot::DiffDriveSpec& nominal,
                           const ControllerConfig& config) {
  std::vector<std::pair<const char*, double>> speeds;
  if (config.type == "square_path") speeds = {{"speed_m_s", config.square_path.speed_m_s}};
  if (config.type == "waypoints") speeds = {{"speed_m_s", config.waypoints.speed_m_s}};
  if (config.type == "wall_following") speeds = {{"speed_m_s", config.wall_following.speed_m_s}};
  if (config.type == "sonar_explorer") {
    speeds = {{"speed_m_s", config.sonar_explorer.speed_m_s},
              {"bump_back_off_speed_m_s", config.sonar_explorer.bump_back_off_speed_m_s}};
  }
  for (const auto& [field, speed_m_s] : speeds) {
    try {
      robot::internal::RequireDrivableSpeed(nominal, field, speed_m_s);
    } catch (const std::invalid_argument& e) {
      fields.FailValidation(e.what());
    }
  }
}

}  // namespace

void ReadControllerConfig(YamlFields fields, const robot::DiffDriveSpec& nominal,
                          ControllerConfig& config) {
  fields.Get("type", &config.type);
  const std::vector<std::string>& built_in = BuiltInControllerTypes();
  const robot::ControllerRegistry& registered = RegisteredAlgorithms().controllers;
  const bool is_registered = registered.Find(config.type) != nullptr;
  if (!is_registered &&
      std::find(built_in.begin(), built_in.end(), config.type) == built_in.end()) {
    std::string known;
    for (const std::string& type : built_in) known += (known.empty() ? "" : ", ") + type;
    for (const std::string& type : registered.Names()) known += ", " + type;
    fields.Fail("type", "unknown controller '" + config.type + "' (known: " + known + ")");
  }
  YamlReadArchive archive(fields);
  VisitChosen(archive, config);
  config.registered = robot::ParameterMap();
  if (is_registered) {
    config.registered = ReadPluginOptions(archive.fields(), {"type", "rate_hz", "steer_by"});
  }
  archive.fields().Finish();
  if (!(config.rate_hz > 0.0)) fields.Fail("rate_hz", "must be a finite number > 0");
  if (is_registered) {
    // Built once now, so a bad or unknown option is reported before the run.
    CheckPluginBuild(fields, [&] { MakeController(config, nominal); });
  }
  if (config.type == "square_path") fields.Validate(config.square_path);
  if (config.type == "waypoints") fields.Validate(config.waypoints);
  if (config.type == "wheel_script") fields.Validate(config.wheel_script);
  if (config.type == "wall_following") fields.Validate(config.wall_following);
  if (config.type == "sonar_explorer") fields.Validate(config.sonar_explorer);
  RequireDrivableSpeeds(fields, nominal, config);
}

YAML::Node WriteControllerConfig(ControllerConfig& config) {
  YamlWriteArchive archive;
  archive("type", config.type);
  VisitChosen(archive, config);
  YAML::Node node = archive.node();
  WritePluginOptions(config.registered, node);
  return node;
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
  if (const auto* entry = RegisteredAlgorithms().controllers.Find(config.type)) {
    return GuardRegistered(
        robot::MakeRegistered(*entry, config.registered, nominal),
        "controller '" + config.type + "' (" + RegisteredBy("controller", config.type) + ")");
  }
  return nullptr;
}

}  // namespace plywood::sim
