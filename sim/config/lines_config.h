#pragma once

#include <yaml-cpp/yaml.h>

#include <memory>
#include <string>
#include <vector>

#include "perception/lines/line_extractor_factory.h"
#include "perception/lines/line_scoring.h"

namespace plywood::sim {

class YamlFields;

// The `lines:` experiment section: which line extractors the post-run scorer runs on every laser
// scan of the run, with their options, the range cut and the scoring gate (docs/lines.md):
//   lines:
//     extractors: [split_and_merge, ransac]   # default: all, built-in and registered
//     range_cut_m: 8                          # only returns at most this far are used
//     scoring: {max_endpoint_distance_m: 0.05, max_alpha_diff_deg: 5, range_noise_sigma_m: 0.01,
//               direction_sigmas: 3, min_overlap_fraction: 0.5, min_observed_rays: 5}
//     split_and_merge: {split_threshold_m: 0.04, breakpoints: {max_m: 0.5}, ...}
//     my_extractor: {min_points: 6}           # a registered one's options (docs/plugins.md)
// Without the section no line scoring runs.
struct LinesConfig {
  bool given = false;
  // In the given order: built-in names (LineExtractorNames()) or registered ones; by default
  // every built-in and every registered extractor.
  std::vector<std::string> extractors;
  double range_cut_m = 1e9;
  perception::LineScoringOptions scoring;
  perception::LineExtractorOptions options;  // options.registered: what YAML gave

  // @throws std::invalid_argument starting with the field name.
  void Validate() const;
};

// @throws ConfigError naming the field.
void ReadLinesConfig(YamlFields fields, LinesConfig& config);
YAML::Node WriteLinesConfig(LinesConfig& config);

// The extractor `name` (built in or registered, sim/config/plugin_loader.h) with the config's
// options. @throws std::invalid_argument as perception::MakeLineExtractor.
std::unique_ptr<perception::LineExtractor> MakeLineExtractor(const std::string& name,
                                                             const LinesConfig& config);

// Keys of `lines:` a registered extractor may not be named: the built-in extractors and the
// section's own keys.
std::vector<std::string> TakenLinesKeys();

}  // namespace plywood::sim
