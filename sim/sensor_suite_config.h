#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>

#include "robot/diff_drive_spec.h"
#include "sim/bumper_sensor.h"
#include "sim/encoder_sensor.h"
#include "sim/gyro_sensor.h"
#include "sim/ir_ring_sensor.h"
#include "sim/ir_scanner_sensor.h"
#include "sim/laser_sensor.h"
#include "sim/sonar_sensor.h"

namespace plywood::sim {

class YamlFields;

// The sensors an experiment enables: a key under `sensors:` turns that sensor on with its defaults
// (`laser: {}`), `enabled: false` turns it off again (handy with --set).
struct SensorSuiteConfig {
  std::optional<LaserOptions> laser;
  std::optional<SonarOptions> sonar;
  std::optional<IrRingOptions> ir_ring;
  std::optional<IrScannerOptions> ir_scanner;
  std::optional<EncoderSensorOptions> encoders;
  std::optional<GyroSensorOptions> gyro;
  std::optional<BumperSensorOptions> bumpers;
};

// `nominal` gives robot-dependent defaults (encoder ticks per revolution).
// @throws ConfigError naming the field; an unknown sensor name is an unknown key.
void ReadSensorSuiteConfig(YamlFields fields, const robot::DiffDriveSpec& nominal,
                           SensorSuiteConfig& suite);
YAML::Node WriteSensorSuiteConfig(SensorSuiteConfig& suite);

}  // namespace plywood::sim
