#include "sim/runner/sensors_the_config_needs.h"

#include <string>

#include "perception/geometric_map/range_fusion.h"
#include "sim/config/config_error.h"
#include "sim/config/controller_config.h"
#include "sim/config/odometry_config.h"

namespace plywood::sim {

// A controller that steers by a sensor the experiment turned off would stand still (or drive
// blind) and still report numbers.
void RequireControllerSensors(const ExperimentConfig& config) {
  const ControllerConfig& c = config.controller;
  const SensorSuiteConfig& s = config.sensors;
  const auto need = [&](bool present, const std::string& field, const std::string& sensor) {
    if (!present) {
      throw ConfigError(config.source_file, field,
                        "this controller needs sensors." + sensor + ", which is off");
    }
  };
  if (c.type == "wall_following") {
    const bool laser = c.wall_following.sensor == robot::WallSensor::kLaser;
    need(laser ? s.laser.has_value() : s.sonar.has_value(), "controller.sensor",
         laser ? "laser" : "sonar");
  }
  if (c.type == "sonar_explorer") need(s.sonar.has_value(), "controller.type", "sonar");
  if (config.geometric_map.given && !s.ir_scanner) {
    throw ConfigError(config.source_file, "geometric_map",
                      "seed 003's map needs sensors.ir_scanner, which is off");
  }
  // The sonar-only map of a run without sonars was empty by construction: recall 0, exit 0.
  if (config.geometric_map.given &&
      config.geometric_map.options.fusion.source == perception::RangeSource::kSonarOnly &&
      !s.sonar) {
    throw ConfigError(config.source_file, "geometric_map.fusion.source",
                      "'sonar' builds the map from sensors.sonar, which is off");
  }
  // Seed 003's map places each IR scan at the record's odometry pose, which a run without an
  // estimator fills with the true pose (MakeScanRecord): the map was built at the truth and
  // reported pose.odometry errors of 0, exit 0 (s49; seed004_ransac's cloud alike, checked there).
  if (config.geometric_map.given) {
    RequireOdometryEstimator(config, "geometric_map", "seed 003 builds its map");
  }
  if (config.lines.given && !s.laser) {
    throw ConfigError(config.source_file, "lines",
                      "line extraction scores the laser's scans, but sensors.laser is off");
  }
}

void RequireOdometrySensors(const ExperimentConfig& config) {
  const SensorSuiteConfig& s = config.sensors;
  if (!config.odometry.enabled.empty() && !s.encoders) {
    throw ConfigError(config.source_file, "odometry",
                      "odometry estimators need sensors.encoders to be enabled");
  }
  for (const std::string& name : config.odometry.enabled) {
    if (EstimatorNeedsGyro(name) && !s.gyro) {
      throw ConfigError(config.source_file, "odometry." + name,
                        "this estimator needs sensors.gyro to be enabled");
    }
  }
}

}  // namespace plywood::sim
