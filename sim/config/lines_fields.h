#pragma once

// The YAML keys of the line extractors' and scorer's options (see sim/config/config_archive.h),
// listed once for the `lines:` section and for protocols that configure an extractor of their own.
// In perception's namespace so argument-dependent lookup finds them from the archives.

#include "perception/lines/hough_extractor.h"
#include "perception/lines/incremental_extractor.h"
#include "perception/lines/line_extractor.h"
#include "perception/lines/line_scoring.h"
#include "perception/lines/polar_neighbour_extractor.h"
#include "perception/lines/ransac_extractor.h"
#include "perception/lines/split_and_merge_extractor.h"

namespace plywood::perception {

// The YAML keys are the option structs' member names (sim/config/config_fields.h convention).
template <typename A>
void VisitFields(A& a, BreakpointOptions& o) {
  a("min_m", o.min_m);
  a("max_m", o.max_m);
  a("lambda_deg", o.lambda_deg);
  a("sigma_m", o.sigma_m);
  a("drop_lone_outliers", o.drop_lone_outliers);
  a("max_missing_beams", o.max_missing_beams);
}

// The segment filter's fields sit flat beside each extractor's own.
template <typename A>
void VisitFields(A& a, SegmentFilterOptions& o) {
  a("min_points", o.min_points);
  a("min_length_m", o.min_length_m);
}

// Flat beside each ordered extractor's own fields, like the segment filter's.
template <typename A>
void VisitFields(A& a, RoundObjectOptions& o) {
  a("reject_round_objects", o.reject_round_objects);
  a("max_round_radius_m", o.max_round_radius_m);
  a("min_round_points", o.min_round_points);
  a("min_round_arc_deg", o.min_round_arc_deg);
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
  a("max_missing_beams", o.max_missing_beams);
}

template <typename A>
void VisitFields(A& a, SplitAndMergeOptions& o) {
  a.Nested("breakpoints", o.breakpoints);
  a("split_threshold_m", o.split_threshold_m);
  a("skip_single_outliers", o.skip_single_outliers);
  a("skip_short_runs", o.skip_short_runs);
  a.Enum(
      "fit", o.fit, [](auto f) { return ToString(f); },
      [](const std::string& t) { return ParseLineFitMethod(t); });
  a.Nested("modal", o.modal);
  VisitFields(a, o.filter);
  VisitFields(a, o.round_objects);
  a("join_across_occluders", o.round_objects.join_across_occluders);
  a("round_past_range_cut", o.round_objects.round_past_range_cut);
}

template <typename A>
void VisitFields(A& a, IncrementalOptions& o) {
  a.Nested("breakpoints", o.breakpoints);
  a("max_distance_m", o.max_distance_m);
  a("seed_points", o.seed_points);
  VisitFields(a, o.filter);
  VisitFields(a, o.round_objects);
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
  a.Nested("breakpoints", o.breakpoints);
  VisitFields(a, o.round_objects);
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
  a.Nested("breakpoints", o.breakpoints);
  VisitFields(a, o.round_objects);
}

template <typename A>
void VisitFields(A& a, LineScoringOptions& o) {
  a("max_endpoint_distance_m", o.max_endpoint_distance_m);
  a("max_alpha_diff_deg", o.max_alpha_diff_deg);
  a("range_noise_sigma_m", o.range_noise_sigma_m);
  a("direction_sigmas", o.direction_sigmas);
  a("min_overlap_fraction", o.min_overlap_fraction);
  a("min_observed_rays", o.min_observed_rays);
}

}  // namespace plywood::perception
