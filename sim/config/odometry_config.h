#pragma once

#include <yaml-cpp/yaml.h>

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "msgs/pose2d.h"
#include "robot/drive/diff_drive_spec.h"
#include "robot/odometry/ekf_odometry.h"
#include "robot/odometry/encoder_odometry.h"
#include "robot/odometry/fused_odometry.h"
#include "robot/odometry/gyro_odometry.h"
#include "robot/odometry/odometry_estimator.h"
#include "robot/odometry/odometry_increments.h"
#include "robot/odometry/weighted_fused_odometry.h"
#include "robot/plugins/parameter_map.h"

namespace plywood::sim {

class YamlFields;

// Which odometry estimators run, each a key under `odometry:` with its options, plus the
// calibration all of them apply to the nominal geometry:
//   odometry:
//     calibration: {wheel_diameter_ratio: 1, track_ratio: 1}
//     encoder: {}
//     gyro: {gain: 1}
//     fused: {}
//     weighted: {encoder_gain: 1, gyro_gain: 1}
//     ekf: {gyro_noise_rad_s: 0.002, ...}
//     my_filter: {gain: 0.5}   # a registered estimator (docs/plugins.md)
// Without an `odometry` section, `encoder` runs whenever sensors.encoders is on.
struct OdometryConfig {
  bool given = false;  // an odometry section was in the YAML
  // In a fixed order, the columns of trajectory.csv: the built-in ones in KnownEstimators()
  // order, then the registered ones in the order they were registered.
  std::vector<std::string> enabled;
  robot::OdometryCalibration calibration;
  robot::EncoderOdometryOptions encoder;
  robot::GyroOdometryOptions gyro;
  robot::FusedOdometryOptions fused;
  robot::WeightedFusedOdometryOptions weighted;
  robot::EkfOdometryOptions ekf;
  std::map<std::string, robot::ParameterMap> registered;  // options of enabled registered ones
};

// Reads the section; `nominal` is the robot's geometry, with which each registered estimator is
// built once to check its options. @throws ConfigError naming the field.
void ReadOdometryConfig(YamlFields fields, const robot::DiffDriveSpec& nominal,
                        OdometryConfig& config);
YAML::Node WriteOdometryConfig(OdometryConfig& config);

// The estimators `config` names (after defaults), each started at X_WR_initial, using the nominal
// geometry with config.calibration applied; registered ones come from
// sim/config/plugin_loader.h. @throws std::invalid_argument when a registered one's factory does.
std::vector<std::pair<std::string, std::unique_ptr<robot::OdometryEstimator>>> MakeEstimators(
    const OdometryConfig& config, const robot::DiffDriveSpec& nominal,
    const msgs::Pose2D& X_WR_initial);

// Names of the built-in estimators, in column order.
const std::vector<std::string>& KnownEstimators();

// Keys of `odometry:` a registered estimator may not be named: the built-in estimators and
// `calibration`.
std::vector<std::string> TakenOdometryKeys();

// Whether the estimator `name` (built in or registered) needs sensors.gyro.
bool EstimatorNeedsGyro(const std::string& name);

}  // namespace plywood::sim
