#pragma once

// The YAML key of every configurable field, listed once per options struct (see config_archive.h).
// Keys are the struct members' names, so a Validate() message "rate_hz: ..." names the YAML key.

#include <vector>

#include "robot/control/square_path_controller.h"
#include "robot/control/wall_following_controller.h"
#include "robot/control/waypoint_controller.h"
#include "robot/control/wheel_script_controller.h"
#include "robot/drive/diff_drive_spec.h"
#include "sim/config/experiment_config.h"
#include "sim/sensors/bumper_sensor.h"
#include "sim/sensors/encoder_sensor.h"
#include "sim/sensors/gyro_sensor.h"
#include "sim/sensors/ir_ring_sensor.h"
#include "sim/sensors/ir_scanner_sensor.h"
#include "sim/sensors/laser_sensor.h"
#include "sim/sensors/sonar_sensor.h"
#include "sim/world/physical_deviation.h"

namespace plywood::sim {

template <typename A>
void VisitFields(A& a, SpawnPose& o) {
  a("x_m", o.x_m);
  a("y_m", o.y_m);
  a("theta_deg", o.theta_deg);
}

template <typename A>
void VisitFields(A& a, PhysicsOptions& o) {
  a("timestep_s", o.timestep_s);
  a.Enum(
      "drive", o.drive, [](DriveMode d) { return ToString(d); },
      [](const std::string& t) { return ParseDriveMode(t); });
}

template <typename A>
void VisitFields(A& a, OutputOptions& o) {
  a("trajectory_rate_hz", o.trajectory_rate_hz);
  a("sensor_logs", o.sensor_logs);
  a("snapshot", o.snapshot);
  a("snapshot_size_px", o.snapshot_size_px);
}

template <typename A>
void VisitFields(A& a, robot::DiffDriveSpec& o) {
  a("wheel_radius_m", o.wheel_radius_m);
  a("track_m", o.track_m);
  a("max_wheel_speed_rad_s", o.max_wheel_speed_rad_s);
  a("encoder_ticks_per_rev", o.encoder_ticks_per_rev);
}

template <typename A>
void VisitFields(A& a, PhysicalDeviation& o) {
  a("wheel_diameter_ratio", o.wheel_diameter_ratio);
  a("track_ratio", o.track_ratio);
}

template <typename A>
void VisitFields(A& a, LaserOptions& o) {
  a("fov_deg", o.fov_deg);
  a("resolution_deg", o.resolution_deg);
  a("range_min_m", o.range_min_m);
  a("range_max_m", o.range_max_m);
  a("range_noise_sigma_m", o.range_noise_sigma_m);
  a("dropout_probability", o.dropout_probability);
  a("mixed_pixels", o.mixed_pixels);
  a("mixed_pixel_min_jump_m", o.mixed_pixel_min_jump_m);
  a("mixed_pixel_probability", o.mixed_pixel_probability);
  a("noise_free", o.noise_free);
  a("rate_hz", o.rate_hz);
}

template <typename A>
void VisitFields(A& a, SonarOptions& o) {
  a("beam_half_angle_deg", o.beam_half_angle_deg);
  a("rays_per_cone", o.rays_per_cone);
  a("incidence_limit_deg", o.incidence_limit_deg);
  a("corner_echoes", o.corner_echoes);
  a("multipath", o.multipath);
  a("edge_echoes", o.edge_echoes);
  a("edge_echo_range_m", o.edge_echo_range_m);
  a("range_min_m", o.range_min_m);
  a("range_max_m", o.range_max_m);
  a("range_noise_fraction", o.range_noise_fraction);
  a("noise_free", o.noise_free);
  a("rate_hz", o.rate_hz);
}

template <typename A>
void VisitFields(A& a, IrRingOptions& o) {
  a("rays_per_beam", o.rays_per_beam);
  a("beam_half_angle_deg", o.beam_half_angle_deg);
  a("incidence_limit_deg", o.incidence_limit_deg);
  a("range_min_m", o.range_min_m);
  a("range_max_m", o.range_max_m);
  a("sigma_m", o.sigma_m);
  a("noise_free", o.noise_free);
  a("rate_hz", o.rate_hz);
}

template <typename A>
void VisitFields(A& a, IrScannerOptions& o) {
  a("fov_deg", o.fov_deg);
  a("resolution_deg", o.resolution_deg);
  a("range_min_m", o.range_min_m);
  a("range_max_m", o.range_max_m);
  a("sigma_m", o.sigma_m);
  a("outlier_probability", o.outlier_probability);
  a("noise_free", o.noise_free);
  a("rate_hz", o.rate_hz);
}

template <typename A>
void VisitFields(A& a, EncoderSensorOptions& o) {
  a("ticks_per_rev", o.ticks_per_rev);
  a("rate_hz", o.rate_hz);
  a("slip_sigma", o.slip_sigma);
  a("noise_free", o.noise_free);
}

template <typename A>
void VisitFields(A& a, GyroSensorOptions& o) {
  a("rate_hz", o.rate_hz);
  a("noise_sigma_rad_s", o.noise_sigma_rad_s);
  a("bias_rad_s", o.bias_rad_s);
  a("bias_random_walk_rad_s_per_sqrt_s", o.bias_random_walk_rad_s_per_sqrt_s);
  a("scale_factor_error", o.scale_factor_error);
  a("quantisation_rad_s", o.quantisation_rad_s);
  a("noise_free", o.noise_free);
}

template <typename A>
void VisitFields(A& a, BumperSensorOptions& o) {
  a("rate_hz", o.rate_hz);
}

template <typename A>
void VisitFields(A& a, robot::SquarePathOptions& o) {
  a("side_m", o.side_m);
  a.Enum(
      "direction", o.direction, [](auto d) { return robot::ToString(d); },
      [](const std::string& t) { return robot::ParseSquareDirection(t); });
  a("laps", o.laps);
  a("speed_m_s", o.speed_m_s);
  a("turn_rate_rad_s", o.turn_rate_rad_s);
  a("accel_m_s2", o.accel_m_s2);
  a("dwell_s", o.dwell_s);
  a("heading_gain_per_s", o.heading_gain_per_s);
  a("cross_track_gain_rad_per_m", o.cross_track_gain_rad_per_m);
  a("position_tolerance_m", o.position_tolerance_m);
  a("heading_tolerance_rad", o.heading_tolerance_rad);
  a("final_turn", o.final_turn);
}

template <typename A>
void VisitFields(A& a, robot::WaypointOptions& o) {
  a.Rows(
      "waypoints", o.waypoints, {"x_m", "y_m"},
      [](const robot::Waypoint& w) {
        return std::vector<double>{w.x_m, w.y_m};
      },
      [](const std::vector<double>& r) {
        return robot::Waypoint{r[0], r[1]};
      });
  a("speed_m_s", o.speed_m_s);
  a("max_turn_rate_rad_s", o.max_turn_rate_rad_s);
  a("accel_m_s2", o.accel_m_s2);
  a("heading_gain_per_s", o.heading_gain_per_s);
  a("turn_in_place_above_rad", o.turn_in_place_above_rad);
  a("reach_tolerance_m", o.reach_tolerance_m);
  a("loop", o.loop);
}

template <typename A>
void VisitFields(A& a, robot::WheelScriptOptions& o) {
  a.Rows(
      "segments", o.segments, {"duration_s", "left_rad_s", "right_rad_s"},
      [](const robot::WheelSegment& s) {
        return std::vector<double>{s.duration_s, s.left_rad_s, s.right_rad_s};
      },
      [](const std::vector<double>& r) {
        return robot::WheelSegment{r[0], r[1], r[2]};
      });
}

template <typename A>
void VisitFields(A& a, robot::WallFollowingOptions& o) {
  a.Enum(
      "side", o.side, [](auto s) { return robot::ToString(s); },
      [](const std::string& t) { return robot::ParseWallSide(t); });
  a.Enum(
      "sensor", o.sensor, [](auto s) { return robot::ToString(s); },
      [](const std::string& t) { return robot::ParseWallSensor(t); });
  a("distance_m", o.distance_m);
  a("speed_m_s", o.speed_m_s);
  a("accel_m_s2", o.accel_m_s2);
  a("max_turn_rate_rad_s", o.max_turn_rate_rad_s);
  a("distance_gain_rad_per_m", o.distance_gain_rad_per_m);
  a("angle_gain_per_s", o.angle_gain_per_s);
  a("max_approach_angle_rad", o.max_approach_angle_rad);
  a("side_window_rad", o.side_window_rad);
  a("front_window_rad", o.front_window_rad);
  a("max_wall_range_m", o.max_wall_range_m);
  a("front_clearance_m", o.front_clearance_m);
  a("lane_half_width_m", o.lane_half_width_m);
  a("memory_s", o.memory_s);
  a("wall_memory_s", o.wall_memory_s);
  a("duration_s", o.duration_s);
}

}  // namespace plywood::sim
