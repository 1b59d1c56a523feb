#include "perception/lines/circle_feature.h"

#include <algorithm>
#include <cmath>

namespace plywood::perception {

std::optional<CircleFeature> CircleFeatureFromFit(const CircleFit& fit,
                                                  std::span<const int> indices,
                                                  const CircleFeatureGates& gates) {
  const int n = static_cast<int>(indices.size());
  if (n < std::max(3, gates.min_points)) return std::nullopt;
  if (!(fit.radius_m > 0.0) || fit.radius_m > gates.max_radius_m) return std::nullopt;
  const double rms_m = std::sqrt(fit.rss_m2 / n);
  if (rms_m > gates.max_rms_sigmas * gates.noise_sigma_m) return std::nullopt;
  if (fit.max_residual_m > gates.max_residual_sigmas * gates.noise_sigma_m) return std::nullopt;
  CircleFeature out;
  out.centre = fit.centre;
  out.radius_m = fit.radius_m;
  out.rms_m = rms_m;
  out.point_indices.assign(indices.begin(), indices.end());
  return out;
}

std::optional<CircleFeature> FitCircleFeature(std::span<const Eigen::Vector2d> points,
                                              std::span<const int> indices,
                                              const CircleFeatureGates& gates) {
  if (static_cast<int>(indices.size()) < std::max(3, gates.min_points)) return std::nullopt;
  const std::optional<CircleFit> fit = FitCircle(points, indices);
  if (!fit) return std::nullopt;
  return CircleFeatureFromFit(*fit, indices, gates);
}

}  // namespace plywood::perception
