#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>

#include "robot/drive/diff_drive_spec.h"
#include "sim/sensors/bumper_sensor.h"
#include "sim/sensors/encoder_sensor.h"
#include "sim/sensors/gyro_sensor.h"
#include "sim/sensors/ir_ring_sensor.h"
#include "sim/sensors/ir_scanner_sensor.h"
#include "sim/sensors/laser_sensor.h"
#include "sim/sensors/sonar_sensor.h"

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
