#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "msgs/range_ring.h"
#include "sim/raycast/ray_caster.h"
#include "sim/sensors/sensor_sites.h"
#include "sim/world/scene.h"

namespace plywood::sim {

// The Magellan Pro's ring of short-range infrared triangulation sensors (Sharp GP2D12 class).
// Each beam is narrow: 1 ray on its axis, or rays_per_beam rays over +-beam_half_angle_deg. The
// reading is the nearest hit among rays whose incidence angle is at most incidence_limit_deg:
// diffuse light comes back from almost any angle, only grazing hits are lost. Nothing within
// range_max_m: echo = false. Readings closer than range_min_m are reported as range_min_m (the real
// sensor's output folds over there; reporting the minimum errs on the safe side). Gaussian noise
// with a fixed sigma_m. Defaults are assumptions: iRobot published no IR figures for the Magellan.
struct IrRingOptions {
  int rays_per_beam = 1;  // 1 or an odd count such as 3
  double beam_half_angle_deg = 2.0;
  double incidence_limit_deg = 75.0;
  double range_min_m = 0.1;
  double range_max_m = 0.8;
  double sigma_m = 0.01;
  bool noise_free = false;
  double rate_hz = 10.0;

  // @throws std::invalid_argument whose message starts with the offending field's name.
  void Validate() const;
};

class IrRingSensor {
 public:
  // "ir_0" .. "ir_15" (the Magellan Pro's ring).
  static std::vector<std::string> DefaultSiteNames();

  // @throws ConfigError naming the robot and the first missing site;
  //         std::invalid_argument from options.Validate() or for an empty `site_names`.
  IrRingSensor(const Scene& scene, const std::vector<std::string>& site_names,
               const IrRingOptions& options, std::uint64_t seed);

  IrRingSensor(const IrRingSensor&) = delete;
  IrRingSensor& operator=(const IrRingSensor&) = delete;

  // One reading per site, in the order of `site_names`, stamped with scene.time_s().
  msgs::RangeRing Measure(const Scene& scene, const RayCaster& caster);
  void Measure(const Scene& scene, const RayCaster& caster, msgs::RangeRing* out);

  const IrRingOptions& options() const { return options_; }

 private:
  const IrRingOptions options_;
  const std::vector<SensorSite> sites_;
  std::vector<Eigen::Vector3d> dirs_S_;
  double cos_incidence_limit_ = 0.0;
  std::mt19937_64 rng_;
};

}  // namespace plywood::sim
