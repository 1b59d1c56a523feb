#pragma once

// The YAML keys of seed 003's geometric-map options (see sim/config/config_archive.h). In
// perception's namespace so argument-dependent lookup finds them from the archives.

#include "perception/geometric_map/geometric_mapper.h"
#include "sim/config/lines_fields.h"

namespace plywood::perception {

template <typename A>
void VisitFields(A& a, FusionOptions& o) {
  a.Enum(
      "source", o.source, [](auto s) { return ToString(s); },
      [](const std::string& t) { return ParseRangeSource(t); });
  a("tau_m", o.tau_m);
  a("sonar_half_angle_deg", o.sonar_half_angle_deg);
  a("fill_half_angle_deg", o.fill_half_angle_deg);
  a("sonar_max_range_m", o.sonar_max_range_m);
}

template <typename A>
void VisitFields(A& a, HistogramOptions& o) {
  a("gamma_beams", o.gamma_beams);
  a("max_virtual_line_m", o.max_virtual_line_m);
  a("angle_bin_deg", o.angle_bin_deg);
  a("distance_bin_m", o.distance_bin_m);
  a("maxima_per_side", o.maxima_per_side);
  a("max_wall_tilt_deg", o.max_wall_tilt_deg);
}

template <typename A>
void VisitFields(A& a, LargestFrameOptions& o) {
  a("d_max_m", o.d_max_m);
  a("min_peak_votes", o.min_peak_votes);
}

template <typename A>
void VisitFields(A& a, PoseCorrectionOptions& o) {
  a("heading", o.heading);
  a("position", o.position);
  a("max_heading_step_deg", o.max_heading_step_deg);
  a("refine_window_deg", o.refine_window_deg);
  a("max_shift_m", o.max_shift_m);
  a("position_bin_m", o.position_bin_m);
  a("min_virtual_lines", o.min_virtual_lines);
  a("min_peak_votes", o.min_peak_votes);
  a("reference_scans", o.reference_scans);
  a("require_reference_support", o.require_reference_support);
  a("refine_position", o.refine_position);
  a("require_peak_support", o.require_peak_support);
}

template <typename A>
void VisitFields(A& a, RoundPieceOptions& o) {
  a("max_object_radius_m", o.max_object_radius_m);
  a("min_sigmas", o.min_sigmas);
  a("noise_floor_m", o.noise_floor_m);
}

template <typename A>
void VisitFields(A& a, SegmentationOptions& o) {
  a("dist_max_m", o.dist_max_m);
  a("min_line_points", o.min_line_points);
  a("min_cluster_points", o.min_cluster_points);
  a("max_cluster_size_m", o.max_cluster_size_m);
  a("r_min_m", o.r_min_m);
  a.Enum(
      "fit", o.fit, [](auto f) { return ToString(f); },
      [](const std::string& t) { return ParseLineFitMethod(t); });
  a.Nested("modal", o.modal);
  a("inlier_distance_m", o.inlier_distance_m);
  a("min_inlier_fraction", o.min_inlier_fraction);
  a("max_intersection_shift_m", o.max_intersection_shift_m);
  a.Nested("round_objects", o.round_objects);
}

template <typename A>
void VisitFields(A& a, AggregationOptions& o) {
  a("inflate_m", o.inflate_m);
  a("max_angle_diff_deg", o.max_angle_diff_deg);
  a("max_endpoint_distance_m", o.max_endpoint_distance_m);
  a("max_gap_m", o.max_gap_m);
  a("cluster_inflate_m", o.cluster_inflate_m);
  a("max_cluster_size_m", o.max_cluster_size_m);
  a("min_observations", o.min_observations);
}

}  // namespace plywood::perception
