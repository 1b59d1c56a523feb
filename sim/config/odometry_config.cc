#include "sim/config/odometry_config.h"

#include <algorithm>

#include "sim/config/config_archive.h"
#include "sim/config/guarded_algorithms.h"
#include "sim/config/plugin_loader.h"
#include "sim/config/plugin_options.h"
#include "sim/config/yaml_fields.h"

namespace plywood::sim {

// The shared increment options sit flat beside each estimator's own.
template <typename A>
void VisitFields(A& a, robot::IncrementOptions& o) {
  a("dead_band_rad", o.dead_band_rad);
  a("counter_modulus", o.counter_modulus);
  a.Enum(
      "integration", o.integration, [](auto i) { return robot::ToString(i); },
      [](const std::string& t) { return robot::ParseIntegration(t); });
}

template <typename A>
void VisitFields(A& a, robot::OdometryCalibration& o) {
  a("wheel_diameter_ratio", o.wheel_diameter_ratio);
  a("track_ratio", o.track_ratio);
}

template <typename A>
void VisitFields(A& a, robot::EncoderOdometryOptions& o) {
  VisitFields(a, o.increments);
  a("gain", o.gain);
}

template <typename A>
void VisitFields(A& a, robot::GyroOdometryOptions& o) {
  VisitFields(a, o.increments);
  a("gain", o.gain);
}

template <typename A>
void VisitFields(A& a, robot::FusedOdometryOptions& o) {
  VisitFields(a, o.increments);
}

template <typename A>
void VisitFields(A& a, robot::WeightedFusedOdometryOptions& o) {
  VisitFields(a, o.increments);
  a("encoder_gain", o.encoder_gain);
  a("gyro_gain", o.gyro_gain);
}

template <typename A>
void VisitFields(A& a, robot::EkfOdometryOptions& o) {
  VisitFields(a, o.increments);
  a("gyro_noise_rad_s", o.gyro_noise_rad_s);
  a("gyro_gain", o.gyro_gain);
  a("gyro_scale_sigma", o.gyro_scale_sigma);
  a("gyro_bias_sigma_rad_s", o.gyro_bias_sigma_rad_s);
  a("gyro_bias_random_walk_rad_s_per_sqrt_s", o.gyro_bias_random_walk_rad_s_per_sqrt_s);
  a("wheel_slip_sigma", o.wheel_slip_sigma);
  a("encoder_turn_sigma", o.encoder_turn_sigma);
  a("wheel_diameter_ratio_sigma", o.wheel_diameter_ratio_sigma);
  a("track_ratio_sigma", o.track_ratio_sigma);
  a("wheel_diameter_ratio_prior", o.wheel_diameter_ratio_prior);
  a("track_ratio_prior", o.track_ratio_prior);
  a("zero_velocity_turn_sigma_rad", o.zero_velocity_turn_sigma_rad);
  a("stop_displacement_along_m", o.stop_displacement_along_m);
  a("stop_displacement_outward_m", o.stop_displacement_outward_m);
  a("stop_displacement_sigma_m", o.stop_displacement_sigma_m);
  a("braking_window_s", o.braking_window_s);
  a("wheel_speed_change_sigma_s", o.wheel_speed_change_sigma_s);
}

namespace {

// Calls f(name, options) for every estimator, in column order.
template <typename F>
void ForEachEstimator(OdometryConfig& c, F&& f) {
  f("encoder", c.encoder);
  f("gyro", c.gyro);
  f("fused", c.fused);
  f("weighted", c.weighted);
  f("ekf", c.ekf);
}

}  // namespace

const std::vector<std::string>& KnownEstimators() {
  static const std::vector<std::string> names{"encoder", "gyro", "fused", "weighted", "ekf"};
  return names;
}

std::vector<std::string> TakenOdometryKeys() {
  std::vector<std::string> keys = KnownEstimators();
  keys.push_back("calibration");
  // The ground truth's own name: trajectory.truth.tum and the truth_* columns of trajectory.csv.
  keys.push_back("truth");
  // controller.steer_by's name for the truth, and its default: an estimator of that name was
  // steered by in every run that enabled it, the truth in none.
  keys.push_back("ground_truth");
  return keys;
}

bool EstimatorNeedsGyro(const std::string& name) {
  if (const auto* entry = RegisteredAlgorithms().odometry_estimators.Find(name)) {
    return entry->needs_gyro;
  }
  return name != "encoder";
}

void ReadOdometryConfig(YamlFields fields, const robot::DiffDriveSpec& nominal,
                        OdometryConfig& config) {
  config.given = true;
  config.enabled.clear();
  config.registered.clear();
  ReadOptions(fields.Child("calibration"), config.calibration);
  ForEachEstimator(config, [&](const char* name, auto& options) {
    if (!fields.Has(name)) return;
    ReadOptions(fields.Child(name), options);
    config.enabled.push_back(name);
  });
  const robot::OdometryEstimatorRegistry& registered = RegisteredAlgorithms().odometry_estimators;
  for (const auto& entry : registered.entries()) {
    if (!fields.Has(entry.name)) continue;
    YamlFields options = fields.Child(entry.name);
    config.registered[entry.name] = ReadPluginOptions(options);
    config.enabled.push_back(entry.name);
  }
  // Finish() names the unknown key and lists the known ones (the estimator names).
  fields.Finish();
  // Build each registered estimator once now, so a bad or unknown option is reported before the
  // run.
  // An iterator, not a structured binding: clang 14 cannot capture bindings in a lambda.
  for (const auto& entry : config.registered) {
    CheckPluginBuild(fields.Child(entry.first), [&] {
      robot::MakeRegistered(*registered.Find(entry.first), entry.second,
                            robot::CalibratedGeometry(nominal, config.calibration), msgs::Pose2D{});
    });
  }
}

YAML::Node WriteOdometryConfig(OdometryConfig& config) {
  YAML::Node node(YAML::NodeType::Map);
  node["calibration"] = WriteOptions(config.calibration);
  ForEachEstimator(config, [&](const char* name, auto& options) {
    if (std::find(config.enabled.begin(), config.enabled.end(), name) != config.enabled.end()) {
      node[name] = WriteOptions(options);
    }
  });
  for (const auto& [name, options] : config.registered) {
    YAML::Node plugin(YAML::NodeType::Map);
    WritePluginOptions(options, plugin);
    if (options.empty()) plugin.SetStyle(YAML::EmitterStyle::Flow);  // "name: {}"
    node[name] = plugin;
  }
  return node;
}

std::vector<std::pair<std::string, std::unique_ptr<robot::OdometryEstimator>>> MakeEstimators(
    const OdometryConfig& config, const robot::DiffDriveSpec& nominal,
    const msgs::Pose2D& X_WR_initial) {
  const robot::OdometryGeometry geometry = robot::CalibratedGeometry(nominal, config.calibration);
  std::vector<std::pair<std::string, std::unique_ptr<robot::OdometryEstimator>>> estimators;
  for (const std::string& name : config.enabled) {
    std::unique_ptr<robot::OdometryEstimator> e;
    if (name == "encoder") {
      e = std::make_unique<robot::EncoderOdometry>(geometry, config.encoder, X_WR_initial);
    } else if (name == "gyro") {
      e = std::make_unique<robot::GyroOdometry>(geometry, config.gyro, X_WR_initial);
    } else if (name == "fused") {
      e = std::make_unique<robot::FusedOdometry>(geometry, config.fused, X_WR_initial);
    } else if (name == "weighted") {
      e = std::make_unique<robot::WeightedFusedOdometry>(geometry, config.weighted, X_WR_initial);
    } else if (name == "ekf") {
      e = std::make_unique<robot::EkfOdometry>(geometry, config.ekf, X_WR_initial);
    } else if (const auto* entry = RegisteredAlgorithms().odometry_estimators.Find(name)) {
      const auto options = config.registered.find(name);
      e = GuardRegistered(
          robot::MakeRegistered(
              *entry, options == config.registered.end() ? robot::ParameterMap() : options->second,
              geometry, X_WR_initial),
          "odometry estimator '" + name + "' (" + RegisteredBy("odometry estimator", name) + ")",
          X_WR_initial);
    }
    if (e) estimators.emplace_back(name, std::move(e));
  }
  return estimators;
}

}  // namespace plywood::sim
