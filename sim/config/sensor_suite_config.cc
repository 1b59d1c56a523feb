#include "sim/config/sensor_suite_config.h"

#include "sim/config/config_archive.h"
#include "sim/config/config_fields.h"
#include "sim/config/yaml_fields.h"

namespace plywood::sim {
namespace {

template <typename Options>
void ReadSensor(YamlFields& parent, const char* key, const Options& defaults,
                std::optional<Options>& slot) {
  if (!parent.Has(key)) {
    parent.Child(key);  // marks it read
    return;
  }
  YamlFields fields = parent.Child(key);
  bool enabled = true;
  fields.Get("enabled", &enabled);
  Options options = defaults;
  ReadOptions(fields, options);
  if (enabled) slot = options;
}

template <typename Options>
void WriteSensor(YAML::Node& node, const char* key, std::optional<Options>& slot) {
  if (slot) node[key] = WriteOptions(*slot);
}

}  // namespace

void ReadSensorSuiteConfig(YamlFields fields, const robot::DiffDriveSpec& nominal,
                           SensorSuiteConfig& suite) {
  ReadSensor(fields, "laser", LaserOptions{}, suite.laser);
  ReadSensor(fields, "sonar", SonarOptions{}, suite.sonar);
  ReadSensor(fields, "ir_ring", IrRingOptions{}, suite.ir_ring);
  ReadSensor(fields, "ir_scanner", IrScannerOptions{}, suite.ir_scanner);
  EncoderSensorOptions encoder_defaults;
  encoder_defaults.ticks_per_rev = nominal.encoder_ticks_per_rev;
  ReadSensor(fields, "encoders", encoder_defaults, suite.encoders);
  ReadSensor(fields, "gyro", GyroSensorOptions{}, suite.gyro);
  ReadSensor(fields, "bumpers", BumperSensorOptions{}, suite.bumpers);
  fields.Finish();
}

YAML::Node WriteSensorSuiteConfig(SensorSuiteConfig& suite) {
  YAML::Node node(YAML::NodeType::Map);
  WriteSensor(node, "laser", suite.laser);
  WriteSensor(node, "sonar", suite.sonar);
  WriteSensor(node, "ir_ring", suite.ir_ring);
  WriteSensor(node, "ir_scanner", suite.ir_scanner);
  WriteSensor(node, "encoders", suite.encoders);
  WriteSensor(node, "gyro", suite.gyro);
  WriteSensor(node, "bumpers", suite.bumpers);
  return node;
}

}  // namespace plywood::sim
