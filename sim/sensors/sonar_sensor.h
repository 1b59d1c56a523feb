#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "msgs/range_ring.h"
#include "sim/raycast/ray_caster.h"
#include "sim/sensors/convex_edges.h"
#include "sim/sensors/sensor_sites.h"
#include "sim/world/scene.h"

namespace plywood::sim {

// A ring of Polaroid 6500-class ultrasonic transducers. Each transducer's beam is a horizontal fan
// of rays_per_cone rays spread evenly over +-beam_half_angle_deg (inclusive); the reading is the
// range of the nearest surface point that sends an echo back:
//  - a direct echo from a ray whose incidence angle (between the reversed ray and the surface
//    normal) is at most incidence_limit_deg: smooth plywood reflects specularly, so oblique hits
//    scatter nothing back (Leonard & Durrant-Whyte 1992; Kuc & Siegel 1987);
//  - a plane's perpendicular foot when it lies inside the beam: a wall whose normal is in the beam
//    echoes from its nearest point (a "region of constant depth"), so one extra ray is cast there
//    and the reading of a tilted wall does not depend on where the fan's rays happen to fall;
//  - a corner echo (corner_echoes): an oblique ray reflected once more by a second surface that
//    comes back towards the transducer (within the beam half-angle) is heard at half the path
//    length (d1 + d2 + |p2 - sensor|) / 2; concave corners are the sonar's strongest targets;
//  - an edge echo (edge_echoes, default off): a convex vertical edge of a static box (a box's
//    corner, a wall's end; ExposedBoxEdges) inside the beam, not hidden behind anything nearer and
//    within edge_echo_range_m, is heard at its straight-line range from any incidence. A convex
//    edge sends no specular echo, but it diffracts (Kuc & Siegel 1987 model it as a line source;
//    Leonard & Durrant-Whyte 1992 list edges with planes, corners and cylinders as the sonar's
//    targets, weaker than planes and heard only at short range). Without it a box's corner met
//    obliquely is silent, and an explorer drives into corners a real ring would hear (round
//    58a, docs/sonar_map/history.md: 0 of 103 touched corners ever echoed). No amplitude model:
//    heard or not;
//  - if nothing echoes, a specular miss: echo = false, unless `multipath` is on, when the
//    central-most hitting ray's single specular bounce is reported as a long reading
//    (d1 + d2 + |p2 - sensor|) / 2 whatever its direction, if that is below range_max_m.
// Readings closer than range_min_m (the receiver's blanking time) are reported as range_min_m, the
// safe side for obstacle avoidance. Noise is Gaussian with sigma = range_noise_fraction * range.
// All transducers fire at one instant per sample: no firing order and no cross-talk.
struct SonarOptions {
  double beam_half_angle_deg = 15.0;  // Polaroid 6500: about 30 deg full opening
  int rays_per_cone = 7;              // odd counts include the axis
  // Not published for plywood; with the 15 deg half-angle a smooth wall stays visible while the
  // transducer axis is within about 35 deg of its normal, which is what Pioneer users see.
  double incidence_limit_deg = 20.0;
  bool corner_echoes = true;
  bool multipath = false;
  bool edge_echoes = false;
  // How far a right-angle edge met on its bisector is heard: where its back-diffracted echo
  // (Keller's wedge coefficient, spreading 1 / r^1.5) falls to what a normal plane returns at the
  // 6500's rated 10.7 m (spreading 1 / 2r), both with ISO 9613-1 air absorption at 49.4 kHz, 20 C,
  // 50 % RH (1.64 dB/m): 2.36 m, rounded down (docs/sonar_map/history.md, round 59a). An upper
  // bound: the ranging module's gain still rises over the first metres, which only shortens it.
  double edge_echo_range_m = 2.3;
  double range_min_m = 0.15;
  double range_max_m = 5.0;
  double range_noise_fraction = 0.01;
  bool noise_free = false;
  // The P3-DX fires its two banks of 8 transducers in parallel at 40 ms per transducer: a whole
  // ring every 320 ms.
  double rate_hz = 3.125;

  // @throws std::invalid_argument whose message starts with the offending field's name.
  void Validate() const;
};

class SonarSensor {
 public:
  // "sonar_0" .. "sonar_15", the ring every Plywood robot carries.
  static std::vector<std::string> DefaultSiteNames();

  // @throws ConfigError naming the robot and the first missing site;
  //         std::invalid_argument from options.Validate() or for an empty `site_names`.
  SonarSensor(const Scene& scene, const std::vector<std::string>& site_names,
              const SonarOptions& options, std::uint64_t seed);

  SonarSensor(const SonarSensor&) = delete;
  SonarSensor& operator=(const SonarSensor&) = delete;

  // One reading per site, in the order of `site_names`, stamped with scene.time_s(). The overload
  // with `out` reuses its buffers.
  msgs::RangeRing Measure(const Scene& scene, const RayCaster& caster);
  void Measure(const Scene& scene, const RayCaster& caster, msgs::RangeRing* out);

  const SonarOptions& options() const { return options_; }

 private:
  // The noise-free echo range of one transducer, or a negative value for no echo. `cone_dirs_W`,
  // `cone_hits` and `cone_found`: its cone's rays (dirs_S_ from X_WS, in order) and their casts.
  double EchoRange(const Eigen::Isometry3d& X_WS, const RayCaster& caster,
                   const Eigen::Vector3d* cone_dirs_W, const RayHit* cone_hits,
                   const bool* cone_found) const;

  // The nearest edge echo of one transducer below `below_m`, or below_m when none is nearer.
  double EdgeEchoRange(const Eigen::Isometry3d& X_WS, const RayCaster& caster,
                       double below_m) const;

  const SonarOptions options_;
  const std::vector<SensorSite> sites_;
  std::vector<ConvexEdge> edges_;        // with edge_echoes only
  std::vector<Eigen::Vector3d> dirs_S_;  // fan directions in the site frame, centre-out
  double cos_incidence_limit_ = 0.0;
  double cos_half_angle_ = 0.0;
  std::mt19937_64 rng_;
  // Scratch of Measure: every site's pose and the cone rays of the whole ring, cast as one batch.
  std::vector<Eigen::Isometry3d> X_WS_;
  std::vector<Eigen::Vector3d> ray_origins_W_, ray_dirs_W_;
  std::vector<RayHit> ray_hits_;
  std::unique_ptr<bool[]> ray_found_;
};

}  // namespace plywood::sim
