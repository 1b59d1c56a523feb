#include "sim/lines_config.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/config_archive.h"
#include "sim/metrics.h"
#include "sim/yaml_fields.h"

namespace plywood::perception {

// The YAML keys are the option structs' member names (sim/config_fields.h convention).
template <typename A>
void VisitFields(A& a, BreakpointOptions& o) {
  a("min_m", o.min_m);
  a("max_m", o.max_m);
  a("lambda_deg", o.lambda_deg);
  a("sigma_m", o.sigma_m);
  a("drop_lone_outliers", o.drop_lone_outliers);
}

// The segment filter's fields sit flat beside each extractor's own.
template <typename A>
void VisitFields(A& a, SegmentFilterOptions& o) {
  a("min_points", o.min_points);
  a("min_length_m", o.min_length_m);
}

template <typename A>
void VisitFields(A& a, ModalFitOptions& o) {
  a("pair_step", o.pair_step);
  a("bin_deg", o.bin_deg);
}

template <typename A>
void VisitFields(A& a, PolarNeighbourOptions& o) {
  a("max_point_distance_m", o.max_point_distance_m);
  a("max_alpha_diff_deg", o.max_alpha_diff_deg);
  a("max_r_diff_m", o.max_r_diff_m);
  a("max_range_m", o.max_range_m);
  a("min_points", o.min_points);
}

template <typename A>
void VisitFields(A& a, SplitAndMergeOptions& o) {
  a.Nested("breakpoints", o.breakpoints);
  a("split_threshold_m", o.split_threshold_m);
  a("skip_single_outliers", o.skip_single_outliers);
  a.Enum(
      "fit", o.fit, [](auto f) { return ToString(f); },
      [](const std::string& t) { return ParseLineFitMethod(t); });
  a.Nested("modal", o.modal);
  VisitFields(a, o.filter);
}

template <typename A>
void VisitFields(A& a, IncrementalOptions& o) {
  a.Nested("breakpoints", o.breakpoints);
  a("max_distance_m", o.max_distance_m);
  a("seed_points", o.seed_points);
  VisitFields(a, o.filter);
}

template <typename A>
void VisitFields(A& a, RansacOptions& o) {
  a("iterations", o.iterations);
  a("distance_threshold_m", o.distance_threshold_m);
  a("min_inliers", o.min_inliers);
  a("max_gap_m", o.max_gap_m);
  a("min_points", o.min_points);
  a("min_length_m", o.min_length_m);
  a("max_lines", o.max_lines);
  a("seed", o.seed);
}

template <typename A>
void VisitFields(A& a, HoughOptions& o) {
  a("theta_bin_deg", o.theta_bin_deg);
  a("rho_bin_m", o.rho_bin_m);
  a("min_votes", o.min_votes);
  a("distance_threshold_m", o.distance_threshold_m);
  a("max_gap_m", o.max_gap_m);
  a("min_points", o.min_points);
  a("min_length_m", o.min_length_m);
  a("max_lines", o.max_lines);
}

template <typename A>
void VisitFields(A& a, LineScoringOptions& o) {
  a("max_alpha_diff_deg", o.max_alpha_diff_deg);
  a("max_r_diff_m", o.max_r_diff_m);
  a("min_overlap_fraction", o.min_overlap_fraction);
  a("min_observed_rays", o.min_observed_rays);
}

}  // namespace plywood::perception

namespace plywood::sim {

using perception::VisitFields;

void LinesConfig::Validate() const {
  if (!(range_cut_m > 0.0)) {
    throw std::invalid_argument("range_cut_m: must be > 0, got " + FormatNumber(range_cut_m));
  }
  const auto& known = perception::LineExtractorNames();
  for (std::size_t i = 0; i < extractors.size(); ++i) {
    if (std::find(known.begin(), known.end(), extractors[i]) == known.end()) {
      std::string list;
      for (const auto& name : known) list += (list.empty() ? "" : ", ") + name;
      throw std::invalid_argument("extractors: unknown extractor '" + extractors[i] +
                                  "' (known: " + list + ")");
    }
    if (std::find(extractors.begin(), extractors.begin() + i, extractors[i]) !=
        extractors.begin() + i) {
      throw std::invalid_argument("extractors: '" + extractors[i] + "' is listed twice");
    }
  }
}

void ReadLinesConfig(YamlFields fields, LinesConfig& config) {
  config.given = true;
  config.extractors = perception::LineExtractorNames();
  if (fields.Has("extractors")) {
    const YAML::Node list = fields.Raw("extractors");
    if (!list.IsSequence()) fields.Fail("extractors", "expected a list of extractor names");
    config.extractors.clear();
    for (const auto& item : list) {
      if (!item.IsScalar()) fields.Fail("extractors", "expected a list of extractor names");
      config.extractors.push_back(item.Scalar());
    }
  }
  fields.Get("range_cut_m", &config.range_cut_m);
  ReadOptions(fields.Child("scoring"), config.scoring);
  ReadOptions(fields.Child("polar_neighbour"), config.options.polar_neighbour);
  ReadOptions(fields.Child("split_and_merge"), config.options.split_and_merge);
  ReadOptions(fields.Child("incremental"), config.options.incremental);
  ReadOptions(fields.Child("ransac"), config.options.ransac);
  ReadOptions(fields.Child("hough"), config.options.hough);
  fields.Finish();
  fields.Validate(config);
}

YAML::Node WriteLinesConfig(LinesConfig& config) {
  YAML::Node node(YAML::NodeType::Map);
  YAML::Node list(YAML::NodeType::Sequence);
  for (const auto& name : config.extractors) list.push_back(name);
  list.SetStyle(YAML::EmitterStyle::Flow);
  node["extractors"] = list;
  node["range_cut_m"] = FormatNumber(config.range_cut_m);
  node["scoring"] = WriteOptions(config.scoring);
  node["polar_neighbour"] = WriteOptions(config.options.polar_neighbour);
  node["split_and_merge"] = WriteOptions(config.options.split_and_merge);
  node["incremental"] = WriteOptions(config.options.incremental);
  node["ransac"] = WriteOptions(config.options.ransac);
  node["hough"] = WriteOptions(config.options.hough);
  return node;
}

}  // namespace plywood::sim
