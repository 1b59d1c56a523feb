#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <vector>

#include "perception/lines/circle_fit.h"

namespace plywood::perception {

// A round object (column, leg, bin) an extractor recognised in a scan, in the points' frame: the
// circle fitted to the points it used (round_object_filter.h decides which runs are round).
struct CircleFeature {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius_m = 0.0;
  double rms_m = 0.0;              // RMS geometric residual of the points used
  std::vector<int> point_indices;  // the scan points used, in scan order (mixed pixels trimmed)

  int num_points() const { return static_cast<int>(point_indices.size()); }
  // Distance of `p` from the circle's rim (| |p - centre| - radius |).
  double RimDistance(const Eigen::Vector2d& p) const {
    return std::abs((p - centre).norm() - radius_m);
  }
};

// The gates every reported circle passes (a real fit, not any three points): a radius within
// (0, max_radius_m], an RMS residual within max_rms_sigmas x the range noise and no point
// farther than max_residual_sigmas x the noise from the rim.
struct CircleFeatureGates {
  double max_radius_m = 0.5;
  double noise_sigma_m = 0.01;
  double max_rms_sigmas = 2.0;
  double max_residual_sigmas = 4.0;
  int min_points = 5;
};

// `fit` (a circle fitted to the points `indices`) as a feature when it passes `gates`.
std::optional<CircleFeature> CircleFeatureFromFit(const CircleFit& fit,
                                                  std::span<const int> indices,
                                                  const CircleFeatureGates& gates);

// Fits a circle to points[indices] (circle_fit.h) and returns it when it passes `gates`.
std::optional<CircleFeature> FitCircleFeature(std::span<const Eigen::Vector2d> points,
                                              std::span<const int> indices,
                                              const CircleFeatureGates& gates);

}  // namespace plywood::perception
