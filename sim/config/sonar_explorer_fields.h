#pragma once

#include "perception/sonar_map/sonar_explorer.h"

namespace plywood::sim {

// YAML keys of `controller: {type: sonar_explorer, ...}`; the map options sit flat beside them.
template <typename A>
void VisitFields(A& a, perception::SonarExplorerOptions& o) {
  a("sonar_model", o.sonar_model);
  a("weights_file", o.weights_file);
  a("grid_half_extent_m", o.grid_half_extent_m);
  a("grid_resolution_m", o.grid_resolution_m);
  a("p_min", o.p_min);
  a("log_odds_limit", o.log_odds_limit);
  a("misses_say_nothing", o.misses_say_nothing);
  a("eps", o.map.eps);
  a("snap_distance_m", o.map.snap_distance_m);
  a("fit_sigma_m", o.map.fit_sigma_m);
  a("min_wall_points", o.map.min_wall_points);
  a("min_obstacle_cells", o.map.min_obstacle_cells);
  a("wall_band_m", o.map.wall_band_m);
  a("min_passage_m", o.map.min_passage_m);
  a("side_free_overrun_m", o.map.side_free_overrun_m);
  a("obstacle_join_m", o.map.obstacle_join_m);
  a("obstacle_wall_join_seen_free", o.map.obstacle_wall_join_seen_free);
  a("obstacle_wall_snap_seen_free", o.map.obstacle_wall_snap_seen_free);
  a("obstacle_free_p", o.map.obstacle_free_p);
  a("fit_obstacle_sides", o.map.fit_obstacle_sides);
  a("obstacle_min_fill", o.map.obstacle_min_fill);
  a("obstacle_trim_keeps_heard_ends", o.map.obstacle_trim_keeps_heard_ends);
  a("obstacle_split_saving", o.map.obstacle_split_saving);
  a("obstacle_from_faces", o.map.obstacle_from_faces);
  a("beam_free_min_passes", o.map.beam_free_min_passes);
  a("obstacle_peel_free", o.map.obstacle_peel_free);
  a("obstacle_peel_net_free_clearance_m", o.map.obstacle_peel_net_free_clearance_m);
  a("obstacle_cut_unheard_gaps", o.map.obstacle_cut_unheard_gaps);
  a("obstacle_cut_min_votes", o.map.obstacle_cut_min_votes);
  a("open_sides_seen_past_m", o.map.open_sides_seen_past_m);
  a("beam_free_axis_tolerance_rad", o.beam_free.axis_tolerance_rad);
  a("beam_free_stop_short_m", o.beam_free.stop_short_m);
  a("beam_free_max_range_m", o.beam_free.max_range_m);
  a("beam_free_oblique_face_max_rad", o.beam_free.oblique_face_max_rad);
  a("beam_free_half_angle_rad", o.beam_free.half_angle_rad);
  a("wall_distance_m", o.wall_distance_m);
  a("perimeter_turn_rad", o.perimeter_turn_rad);
  a("perimeter_max_s", o.perimeter_max_s);
  a("perimeter_stuck_turn_rad", o.perimeter_stuck_turn_rad);
  a("perimeter_avoids_contacts", o.perimeter_avoids_contacts);
  a("perimeter_front_clearance_m", o.perimeter_front_clearance_m);
  a("speed_m_s", o.speed_m_s);
  a("turn_rate_rad_s", o.turn_rate_rad_s);
  a("replan_period_s", o.replan_period_s);
  a("visit_decay", o.visit_decay);
  a("unvisited_utility", o.unvisited_utility);
  a("place_size_m", o.place_size_m);
  a("perimeter_min_m", o.perimeter_min_m);
  a("visit_radius_m", o.visit_radius_m);
  a("clearance_m", o.clearance_m);
  a("stop_range_m", o.stop_range_m);
  a("max_wheel_accel_rad_s2", o.max_wheel_accel_rad_s2);
  a("bump_back_off_s", o.bump_back_off_s);
  a("bump_back_off_speed_m_s", o.bump_back_off_speed_m_s);
  a("bump_stops_wheels", o.bump_stops_wheels);
  a("bump_wedge_turns", o.bump_wedge_turns);
  a("front_margin_m", o.front_margin_m);
  a("waypoint_tolerance_m", o.waypoint_tolerance_m);
  a("explore_max_s", o.explore_max_s);
  a("frontier_min_cells", o.frontier_min_cells);
  a("robot_radius_m", o.robot_radius_m);
  a("path_clearance_m", o.path_clearance_m);
  a("narrow_clearance_m", o.narrow_clearance_m);
  a("squeeze_clearance_m", o.squeeze_clearance_m);
  a("contact_clearance_m", o.contact_clearance_m);
  a("frontier_view_m", o.frontier_view_m);
  a("frontier_wall_band_m", o.frontier_wall_band_m);
  a("circle_obstacles", o.circle_obstacles);
  a("circuit_reach_m", o.circuit_reach_m);
  a("circuit_narrow", o.circuit_narrow);
  a("circuit_max_s", o.circuit_max_s);
  a("circuit_same_m", o.circuit_same_m);
  a("complete_unknown_share_max", o.complete_unknown_share_max);
  a("complete_room_check", o.complete_room_check);
  a("last_frontier_through_axis_free", o.last_frontier_through_axis_free);
  a("last_frontier_at_body_clearance", o.last_frontier_at_body_clearance);
}

}  // namespace plywood::sim
