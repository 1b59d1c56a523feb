#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "perception/lines/line_extractor_factory.h"
#include "perception/lines/line_scoring.h"

namespace plywood::sim {

class YamlFields;

// The `lines:` experiment section: which line extractors the post-run scorer runs on every laser
// scan of the run, with their options, the range cut and the scoring gate (docs/lines.md):
//   lines:
//     extractors: [split_and_merge, ransac]   # default: all five
//     range_cut_m: 8                          # only returns at most this far are used
//     scoring: {max_alpha_diff_deg: 5, max_r_diff_m: 0.05, min_overlap_fraction: 0.5,
//               min_observed_rays: 5}
//     split_and_merge: {split_threshold_m: 0.04, breakpoints: {max_m: 0.5}, ...}
// Without the section no line scoring runs.
struct LinesConfig {
  bool given = false;
  std::vector<std::string> extractors;  // in the given order; names from LineExtractorNames()
  double range_cut_m = 1e9;
  perception::LineScoringOptions scoring;
  perception::LineExtractorOptions options;

  // @throws std::invalid_argument starting with the field name.
  void Validate() const;
};

// @throws ConfigError naming the field.
void ReadLinesConfig(YamlFields fields, LinesConfig& config);
YAML::Node WriteLinesConfig(LinesConfig& config);

}  // namespace plywood::sim
