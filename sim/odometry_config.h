#pragma once

#include <yaml-cpp/yaml.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "msgs/pose2d.h"
#include "robot/diff_drive_spec.h"
#include "robot/odometry_estimator.h"

namespace plywood::sim {

class YamlFields;

// Which odometry estimators run. In YAML each is a key under `odometry:` with its options:
//   odometry: {encoder: {}}
// Without an `odometry` section, `encoder` runs whenever sensors.encoders is on.
struct OdometryConfig {
  bool given = false;                // an odometry section was in the YAML
  std::vector<std::string> enabled;  // in a fixed order: the columns of trajectory.csv
};

// @throws ConfigError naming the field.
void ReadOdometryConfig(YamlFields fields, OdometryConfig& config);
YAML::Node WriteOdometryConfig(OdometryConfig& config);

// The estimators `config` names (after defaults), each started at X_WR_initial.
std::vector<std::pair<std::string, std::unique_ptr<robot::OdometryEstimator>>> MakeEstimators(
    const OdometryConfig& config, const robot::DiffDriveSpec& nominal,
    const msgs::Pose2D& X_WR_initial);

// Names of all estimators, in column order.
const std::vector<std::string>& KnownEstimators();

}  // namespace plywood::sim
