#include "sim/odometry_config.h"

#include <algorithm>

#include "robot/encoder_odometry.h"
#include "sim/config_archive.h"
#include "sim/yaml_fields.h"

namespace plywood::sim {

const std::vector<std::string>& KnownEstimators() {
  static const std::vector<std::string> names{"encoder"};
  return names;
}

void ReadOdometryConfig(YamlFields fields, OdometryConfig& config) {
  config.given = true;
  config.enabled.clear();
  for (const std::string& name : KnownEstimators()) {
    if (!fields.Has(name)) continue;
    YamlFields options = fields.Child(name);
    options.Finish();  // the encoder estimator has no options
    config.enabled.push_back(name);
  }
  fields.Finish();
}

YAML::Node WriteOdometryConfig(OdometryConfig& config) {
  YAML::Node node(YAML::NodeType::Map);
  for (const std::string& name : config.enabled) node[name] = YAML::Node(YAML::NodeType::Map);
  return node;
}

std::vector<std::pair<std::string, std::unique_ptr<robot::OdometryEstimator>>> MakeEstimators(
    const OdometryConfig& config, const robot::DiffDriveSpec& nominal,
    const msgs::Pose2D& X_WR_initial) {
  std::vector<std::pair<std::string, std::unique_ptr<robot::OdometryEstimator>>> estimators;
  for (const std::string& name : config.enabled) {
    if (name == "encoder") {
      estimators.emplace_back(name,
                              std::make_unique<robot::EncoderOdometry>(nominal, X_WR_initial));
    }
  }
  return estimators;
}

}  // namespace plywood::sim
