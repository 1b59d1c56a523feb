#include "sim/sensors/sonar_sensor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "msgs/angle_units.h"
#include "msgs/shortest_number.h"
#include "sim/config/require_field.h"
#include "sim/sensors/foot_in_beam.h"
#include "sim/sensors/noise_draws.h"
#include "sim/sensors/planar_fan.h"

namespace plywood::sim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Bounce rays start at least this far off the surface so they do not hit it again.
constexpr double kSurfaceOffsetM = 1e-6;
// A ray cast at an edge that stops this much short of it met something in front of the edge; one
// that reaches it (rounding within this) met the edge's own faces.
constexpr double kEdgeOcclusionToleranceM = 1e-3;
// A bounce ray is cast this far beyond the nearest echo so far: far above the rounding (~1e-15
// relative to the coordinates) of the path it would make.
constexpr double kBounceSlackM = 1e-6;

}  // namespace

void SonarOptions::Validate() const {
  RequireField(std::isfinite(beam_half_angle_deg) && beam_half_angle_deg >= 0.0 &&
                   beam_half_angle_deg < 90.0,
               "beam_half_angle_deg", "must be in [0, 90)", beam_half_angle_deg);
  RequireField(rays_per_cone >= 1 && rays_per_cone <= 1000, "rays_per_cone", "must be in [1, 1000]",
               rays_per_cone);
  RequireField(std::isfinite(incidence_limit_deg) && incidence_limit_deg >= 0.0 &&
                   incidence_limit_deg <= 90.0,
               "incidence_limit_deg", "must be in [0, 90]", incidence_limit_deg);
  RequireField(std::isfinite(range_max_m) && range_max_m > 0.0, "range_max_m", "must be > 0",
               range_max_m);
  RequireField(std::isfinite(range_min_m) && range_min_m >= 0.0 && range_min_m < range_max_m,
               "range_min_m", "must be in [0, range_max_m)", range_min_m);
  RequireField(std::isfinite(range_noise_fraction) && range_noise_fraction >= 0.0,
               "range_noise_fraction", "must be >= 0", range_noise_fraction);
  // As the laser's sigma bound: a sigma beyond the reading itself leaves no geometry in it.
  RequireField(range_noise_fraction <= 1.0, "range_noise_fraction",
               "must be at most 1 (sigma = range_noise_fraction x range: more is noise larger than "
               "the reading)",
               range_noise_fraction);
  RequireField(std::isfinite(edge_echo_range_m) && edge_echo_range_m > 0.0, "edge_echo_range_m",
               "must be > 0", edge_echo_range_m);
  RequireField(std::isfinite(rate_hz) && rate_hz > 0.0, "rate_hz", "must be > 0", rate_hz);
  // Read only for edge echoes: another value with them off ran without a word (s62). The default
  // still passes, as config.yaml writes it for every sonar.
  if (!edge_echoes && edge_echo_range_m != SonarOptions{}.edge_echo_range_m) {
    throw std::invalid_argument(
        "edge_echo_range_m: " + msgs::ShortestNumber(edge_echo_range_m) +
        " is read only with edge_echoes: true (it is false, so the value would change nothing): "
        "set edge_echoes: true, or leave edge_echo_range_m at " +
        msgs::ShortestNumber(SonarOptions{}.edge_echo_range_m));
  }
}

std::vector<std::string> SonarSensor::DefaultSiteNames() { return NumberedSiteNames("sonar_", 16); }

SonarSensor::SonarSensor(const Scene& scene, const std::vector<std::string>& site_names,
                         const SonarOptions& options, std::uint64_t seed)
    : options_((options.Validate(), options)),
      sites_(RequireSensorSites(scene, site_names, "the sonar ring", options_.range_max_m)),
      rng_(seed) {
  // Centre-out order, so the first ray that hits is the central-most one (the multipath bounce).
  std::vector<double> angles_rad =
      SymmetricFanAnglesRad(options_.beam_half_angle_deg, options_.rays_per_cone);
  std::stable_sort(angles_rad.begin(), angles_rad.end(),
                   [](double a, double b) { return std::abs(a) < std::abs(b) - 1e-12; });
  dirs_S_ = PlanarDirections(angles_rad);
  cos_incidence_limit_ = std::cos(options_.incidence_limit_deg * kDegToRad);
  cos_half_angle_ = std::cos(options_.beam_half_angle_deg * kDegToRad);
  if (options_.edge_echoes) edges_ = ExposedBoxEdges(scene.model());
}

msgs::RangeRing SonarSensor::Measure(const Scene& scene, const RayCaster& caster) {
  msgs::RangeRing out;
  Measure(scene, caster, &out);
  return out;
}

void SonarSensor::Measure(const Scene& scene, const RayCaster& caster, msgs::RangeRing* out) {
  out->time_s = scene.time_s();
  out->range_min_m = options_.range_min_m;
  out->range_max_m = options_.range_max_m;
  out->readings.resize(sites_.size());
  // The cone rays of every transducer first, as one batch (the same hits as ray by ray).
  const std::size_t per_cone = dirs_S_.size(), rays = sites_.size() * per_cone;
  X_WS_.resize(sites_.size());
  ray_origins_W_.resize(rays);
  ray_dirs_W_.resize(rays);
  ray_hits_.resize(rays);
  if (!ray_found_) ray_found_ = std::make_unique<bool[]>(rays);
  for (std::size_t k = 0; k < sites_.size(); ++k) {
    X_WS_[k] = scene.SitePoseInWorld(sites_[k].id);
    const Eigen::Matrix3d R_WS = X_WS_[k].linear();
    const Eigen::Vector3d p_WS = X_WS_[k].translation();
    for (std::size_t j = 0; j < per_cone; ++j) {
      ray_origins_W_[k * per_cone + j] = p_WS;
      ray_dirs_W_[k * per_cone + j] = R_WS * dirs_S_[j];
    }
  }
  caster.CastBatch(ray_origins_W_.data(), ray_dirs_W_.data(), static_cast<int>(rays),
                   options_.range_max_m, /*with_normal=*/true, ray_hits_.data(), ray_found_.get());
  NormalDraws unit_noise;  // a new pair state per ring, as before
  for (std::size_t k = 0; k < sites_.size(); ++k) {
    msgs::RangeReading& reading = out->readings[k];
    reading.X_RS = sites_[k].X_RS;
    double range_m = EchoRange(X_WS_[k], caster, ray_dirs_W_.data() + k * per_cone,
                               ray_hits_.data() + k * per_cone, ray_found_.get() + k * per_cone);
    if (range_m >= 0.0 && !options_.noise_free) {
      range_m += options_.range_noise_fraction * range_m * unit_noise(rng_);
    }
    reading.echo = range_m >= 0.0 && range_m < options_.range_max_m;
    reading.range_m = reading.echo ? std::max(range_m, options_.range_min_m) : 0.0;
  }
}

double SonarSensor::EchoRange(const Eigen::Isometry3d& X_WS, const RayCaster& caster,
                              const Eigen::Vector3d* cone_dirs_W, const RayHit* cone_hits,
                              const bool* cone_found) const {
  const Eigen::Matrix3d R_WS = X_WS.linear();
  const Eigen::Vector3d p_WS = X_WS.translation();
  const double range_max_m = options_.range_max_m;
  const bool need_bounce = options_.corner_echoes || options_.multipath;

  double best_m = kInf;
  double multipath_m = kInf;  // the central-most hitting ray's bounce
  bool central_seen = false;
  double foot_m = kInf;  // nearest perpendicular foot of a hit plane that lies inside the beam
  Eigen::Vector3d foot_dir_S = Eigen::Vector3d::UnitX();
  RayHit hit2;
  for (std::size_t j = 0; j < dirs_S_.size(); ++j) {
    if (!cone_found[j]) continue;
    const RayHit& hit = cone_hits[j];
    if (hit.distance_m >= range_max_m) continue;
    const Eigen::Vector3d& dir_W = cone_dirs_W[j];
    const bool is_central = !central_seen;
    central_seen = true;
    const Eigen::Vector3d& n_W = hit.normal_W;
    const double cos_incidence = -dir_W.dot(n_W);

    // Where, within the fan's plane, the hit surface's plane comes nearest.
    const Eigen::Vector3d n_S = R_WS.transpose() * n_W;
    if (FootMayBeInBeam(n_S.x(), n_S.y(), cos_half_angle_)) {
      const double foot_len = std::hypot(n_S.x(), n_S.y());
      if (foot_len > 1e-9 && -n_S.x() / foot_len >= cos_half_angle_) {
        const double t = hit.distance_m * cos_incidence / foot_len;
        if (t < foot_m) {
          foot_m = t;
          foot_dir_S = Eigen::Vector3d(-n_S.x() / foot_len, -n_S.y() / foot_len, 0.0);
        }
      }
    }

    if (cos_incidence >= cos_incidence_limit_) {
      best_m = std::min(best_m, hit.distance_m);
      continue;
    }
    // An oblique hit: the only way back is a second reflection. The round trip is at least 2 d1.
    if (!need_bounce || (hit.distance_m >= best_m && !(is_central && options_.multipath))) {
      continue;
    }
    const Eigen::Vector3d p1_W = p_WS + hit.distance_m * dir_W;
    const Eigen::Vector3d r1_W = dir_W - 2.0 * dir_W.dot(n_W) * n_W;
    // Start the bounce a little way along its own line, so d2 stays exact.
    const double skip_m = std::min(1e-3, kSurfaceOffsetM / std::max(cos_incidence, 1e-6));
    // A corner echo counts only below best_m and range_max_m, and its path (d1 + d2 + back) / 2
    // is at least d2 (back >= d2 - d1): a second hit beyond them changes nothing, so the ray stops
    // there (kBounceSlackM covers the path's rounding). So does the central ray's multipath
    // bounce: its path is returned only when no echo came below range_max_m, so best_m is then
    // still at least range_max_m here, and only a path below range_max_m is returned.
    const double bounce_range_m =
        std::min(2.0 * range_max_m - hit.distance_m, std::min(best_m, range_max_m) + kBounceSlackM);
    if (!caster.Cast(p1_W + skip_m * r1_W, r1_W, bounce_range_m, &hit2)) {
      continue;
    }
    const double d2_m = skip_m + hit2.distance_m;
    const Eigen::Vector3d p2_W = p1_W + d2_m * r1_W;
    const Eigen::Vector3d back_W = p_WS - p2_W;
    const double back_m = back_W.norm();
    const double path_m = (hit.distance_m + d2_m + back_m) / 2.0;
    if (is_central) multipath_m = path_m;
    if (options_.corner_echoes && back_m > 0.0) {
      const Eigen::Vector3d r2_W = r1_W - 2.0 * r1_W.dot(hit2.normal_W) * hit2.normal_W;
      if (r2_W.dot(back_W) >= cos_half_angle_ * back_m) best_m = std::min(best_m, path_m);
    }
  }

  if (foot_m < best_m) {
    const Eigen::Vector3d dir_W = R_WS * foot_dir_S;
    RayHit foot;
    // The foot only lowers best_m: a hit beyond it changes nothing.
    if (caster.Cast(p_WS, dir_W, std::min(range_max_m, best_m), &foot) &&
        foot.distance_m < range_max_m && -dir_W.dot(foot.normal_W) >= cos_incidence_limit_) {
      best_m = std::min(best_m, foot.distance_m);
    }
  }
  if (options_.edge_echoes) best_m = EdgeEchoRange(X_WS, caster, best_m);
  if (best_m < range_max_m) return best_m;
  if (options_.multipath && multipath_m < range_max_m) return multipath_m;
  return -1.0;
}

double SonarSensor::EdgeEchoRange(const Eigen::Isometry3d& X_WS, const RayCaster& caster,
                                  double below_m) const {
  const Eigen::Vector3d axis_W = X_WS.linear().col(0);
  const Eigen::Vector3d p_WS = X_WS.translation();
  // Only an edge nearer than every echo so far (and within its own and the sensor's range) counts.
  double bound_m = std::min({below_m, options_.edge_echo_range_m, options_.range_max_m});
  double best_m = below_m;
  RayHit hit;
  for (const ConvexEdge& edge : edges_) {
    if (p_WS.z() < edge.z_min_m || p_WS.z() > edge.z_max_m) continue;
    // The edge's nearest point is level with the transducer: the fan's plane cuts it there.
    const Eigen::Vector3d to_edge_W(edge.point_W.x() - p_WS.x(), edge.point_W.y() - p_WS.y(), 0.0);
    const double range_m = to_edge_W.norm();
    if (range_m >= bound_m || range_m <= 0.0) continue;
    const Eigen::Vector3d dir_W = to_edge_W / range_m;
    if (axis_W.dot(dir_W) < cos_half_angle_) continue;  // outside the beam
    if (caster.Cast(p_WS, dir_W, range_m, &hit) &&
        hit.distance_m < range_m - kEdgeOcclusionToleranceM) {
      continue;  // hidden behind something nearer, or behind the box's own faces
    }
    best_m = bound_m = range_m;
  }
  return best_m;
}

}  // namespace plywood::sim
