#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "msgs/laser_scan.h"
#include "sim/raycast/ray_caster.h"
#include "sim/sensors/planar_scan.h"
#include "sim/sensors/scan_measurement.h"
#include "sim/world/scene.h"

namespace plywood::sim {

// SICK LMS 200 as configured over its serial protocol. Ranges are reported in mm in the 8, 16 and
// 32 m modes and in cm in the 80 m mode (LMS 200 Technical Description); the scan is quantised to
// that unit. Beam i points at -fov_deg/2 + i * resolution_deg from the sensor's x axis.
struct LaserOptions {
  double fov_deg = 180.0;             // (0, 180]; must be a whole number of resolution_deg steps
  double resolution_deg = 0.5;        // 0.25, 0.5 or 1 (the LMS 200's angular modes)
  double range_min_m = 0.0;           // closer points are reported as they are (IsReturn is false)
  double range_max_m = 8.0;           // 8, 16, 32 (mm modes) or 80 (cm mode)
  double range_noise_sigma_m = 0.01;  // Gaussian; the LMS 200 data sheet gives +-15 mm typ.
  double dropout_probability = 0.0;   // a beam independently reports range_max_m
  // Mixed pixels (Ye & Borenstein, ICRA 2002): where two neighbouring beams' true ranges differ by
  // more than mixed_pixel_min_jump_m at a depth edge (the far hit is off the near surface, so not
  // a wall seen at a grazing angle), the beam on the far side straddles both surfaces with
  // probability mixed_pixel_probability and reports a range uniform between them.
  bool mixed_pixels = false;
  double mixed_pixel_min_jump_m = 0.1;
  double mixed_pixel_probability = 0.5;
  // Exact geometric ranges: no noise, dropouts, mixed pixels or quantisation.
  bool noise_free = false;
  double rate_hz = 10.0;  // the LMS 200 can deliver up to 75 Hz

  // @throws std::invalid_argument whose message starts with the offending field's name.
  void Validate() const;
  // Size of the reported range unit (m): 0.001 in the mm modes, 0.01 in the 80 m mode.
  double RangeResolutionM() const;
  int BeamCount() const;
};

// Simulates the laser at a site of the robot ("laser" on the P3-DX). Rays leave the site's origin
// in the site's x-y plane, so the scan tilts with the robot.
class LaserSensor {
 public:
  // @throws ConfigError naming the robot and the site when the robot has no such site;
  //         std::invalid_argument from options.Validate().
  LaserSensor(const Scene& scene, const std::string& site_name, const LaserOptions& options,
              std::uint64_t seed);

  LaserSensor(const LaserSensor&) = delete;
  LaserSensor& operator=(const LaserSensor&) = delete;

  // One scan at the scene's current state, stamped with scene.time_s(). The overload with `out`
  // reuses its buffers (no allocation after the first call).
  ScanMeasurement Measure(const Scene& scene, const RayCaster& caster);
  void Measure(const Scene& scene, const RayCaster& caster, ScanMeasurement* out);

  const LaserOptions& options() const { return options_; }
  int site_id() const { return geometry_.site().id; }

 private:
  // Whether the true ranges of neighbouring beams `near` < `far` (in range) straddle a depth edge.
  bool IsDepthEdge(int near, int far, double angle_increment_rad) const;

  const LaserOptions options_;
  const PlanarScan geometry_;
  std::vector<double> true_ranges_m_;  // scratch: geometric range per beam (range_max: no hit)
  std::mt19937_64 rng_;
};

}  // namespace plywood::sim
