#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "robot/drive/diff_drive_spec.h"
#include "sim/config/controller_config.h"
#include "sim/config/geometric_map_config.h"
#include "sim/config/lines_config.h"
#include "sim/config/odometry_config.h"
#include "sim/config/sensor_suite_config.h"
#include "sim/world/drive_mode.h"
#include "sim/world/physical_deviation.h"

namespace plywood::sim {

struct SpawnPose {
  double x_m = 0.0;
  double y_m = 0.0;
  double theta_deg = 0.0;
  // theta_deg within one turn either way (kMaxSpawnTurnDeg, sim/world/world_spawns.h).
  void Validate() const;
};

struct PhysicsOptions {
  double timestep_s = 0.01;
  // contact (MuJoCo's contacts, the default) or planar (no mj_step: sim/world/planar_drive.h).
  DriveMode drive = DriveMode::kContact;
  void Validate() const;
};

// What a run writes besides config.yaml, trajectory.csv and metrics.json.
struct OutputOptions {
  double trajectory_rate_hz = 10.0;  // rows of trajectory.csv per simulated second
  bool sensor_logs = true;           // laser.log (CARMEN FLASER), sonar.csv, ir.csv, ...
  bool snapshot = true;              // snapshot.png
  int snapshot_size_px = 1024;       // longer side
  void Validate() const;
};

// One experiment, as read from YAML: everything that determines a run. Two runs of the same config
// give byte-identical trajectory.csv and metrics.json.
struct ExperimentConfig {
  std::string source_file;  // the YAML it came from, for error messages
  // The key paths given with --set (a sweep's axes and profiles among them), canonical
  // (CanonicalKeyPath), in order: what a user set explicitly rather than the file. Not a setting
  // (config.yaml does not record it): only for refusing a --set that would change nothing.
  std::vector<std::string> set_keys;
  std::string name;
  // "single" (one run) or a registered multi-run protocol (eval/protocol.h) such as "umbmark".
  // A protocol reads its own options from the top-level section named after it, kept here raw
  // and read strictly by the protocol (YamlFields over protocol_options).
  std::string protocol = "single";
  YAML::Node protocol_options;
  std::uint64_t seed = 1;
  // Shared libraries that add algorithms (docs/plugins.md), resolved like `world`; loaded before
  // anything else is read, so the sections below can name what they registered.
  std::vector<std::filesystem::path> plugins;
  double duration_s = 60.0;
  std::string world;                 // as written in the YAML
  std::filesystem::path world_path;  // resolved
  std::string robot = "p3dx";        // a name from the robot catalog
  SpawnPose spawn;
  robot::DiffDriveSpec nominal;  // what the robot's software believes (defaults per robot)
  PhysicalDeviation deviation;   // how the simulated robot really is
  PhysicsOptions physics;
  ControllerConfig controller;
  SensorSuiteConfig sensors;
  OdometryConfig odometry;
  LinesConfig lines;                 // post-run line-extraction scoring (docs/lines.md)
  GeometricMapConfig geometric_map;  // post-run seed 003 map (docs/geometric_map.md)
  OutputOptions output;
};

// Loads an experiment from `yaml_path`, applying "--set key.path=value" overrides first.
// Relative paths inside (world) resolve against the YAML's folder, then against the data root.
// @throws ConfigError naming the file and the field for every problem found.
ExperimentConfig LoadExperimentConfig(const std::filesystem::path& yaml_path,
                                      const std::vector<std::string>& overrides = {});

// Same, from YAML text (tests, fuzzing); `source` names it in errors, `base_dir` resolves paths.
ExperimentConfig ParseExperimentConfig(const std::string& yaml_text, const std::string& source,
                                       const std::filesystem::path& base_dir,
                                       const std::vector<std::string>& overrides = {});

// For a protocol that places data at the record's odometry pose, which a run without an estimator
// fills with the true pose (its figures would be the truth's, exit 0): refuses such a run, naming
// `field` and what the protocol does there ("seed 003 builds its map").
// @throws ConfigError when config.odometry enables no estimator.
void RequireOdometryEstimator(const ExperimentConfig& config, const std::string& field,
                              const std::string& what_uses_the_pose);

// The key path an override of `key_path` sets: the long name of a short one a user may write
// (sensors.laser.sigma_m is sensors.laser.range_noise_sigma_m), else `key_path` itself. Two
// overrides set the same value exactly when their canonical paths are equal.
std::string CanonicalKeyPath(const std::string& key_path);

// The fully resolved config (every default spelled out), loadable again by LoadExperimentConfig.
std::string ExperimentConfigToYaml(const ExperimentConfig& config);

}  // namespace plywood::sim
