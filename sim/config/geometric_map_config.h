#pragma once

#include <yaml-cpp/yaml.h>

#include "perception/geometric_map/geometric_mapper.h"
#include "perception/lines/line_scoring.h"

namespace plywood::sim {

class YamlFields;

// The `geometric_map:` experiment section: seed 003's map, built after the run from every IR scan
// (sensors.ir_scanner) fused with the sonar ring (sensors.sonar) at the odometry pose, and scored
// against the ground truth (docs/geometric_map.md):
//   geometric_map:
//     fusion: {source: fused, tau_m: 0.1}         # source: fused | ir | sonar
//     histograms: {gamma_beams: 3, angle_bin_deg: 1}
//     frame: {d_max_m: 3}
//     correction: {heading: true, position: true}
//     segmentation: {dist_max_m: 0.15, r_min_m: 0.03, fit: modal}
//     aggregation: {max_angle_diff_deg: 5, max_endpoint_distance_m: 0.06}
//     max_sonar_age_s: 0.1
//     scoring: {max_endpoint_distance_m: 0.05, max_alpha_diff_deg: 5, range_noise_sigma_m: 0.01,
//               direction_sigmas: 3, min_overlap_fraction: 0.5, min_observed_rays: 5}
// Without the section no map is built.
struct GeometricMapConfig {
  bool given = false;
  perception::GeometricMapOptions options;
  // The sonar ring fused with an IR scan is the one read nearest in time, at most this far from
  // the scan (without motion compensation: give both sensors the same rate).
  double max_sonar_age_s = 0.1;
  perception::LineScoringOptions scoring;

  // @throws std::invalid_argument starting with the field name.
  void Validate() const;
};

// @throws ConfigError naming the field.
void ReadGeometricMapConfig(YamlFields fields, GeometricMapConfig& config);
YAML::Node WriteGeometricMapConfig(GeometricMapConfig& config);

}  // namespace plywood::sim
