#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>

namespace plywood::perception {

// A circle fitted to points, with the geometric residuals |(|p - centre| - radius)|.
struct CircleFit {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius_m = 0.0;
  double rss_m2 = 0.0;          // sum of squared geometric residuals
  double max_residual_m = 0.0;  // largest geometric residual
};

// Least-squares circle through points[indices]: the algebraic fit of Kasa ("A circle fitting
// procedure and its error analysis", IEEE Trans. Instrum. Meas. 1976), centred on the points'
// mean for conditioning, refined by Gauss-Newton on the geometric residuals (the algebraic fit is
// biased towards small circles on short arcs). Nothing for fewer than 3 points or collinear ones.
std::optional<CircleFit> FitCircle(std::span<const Eigen::Vector2d> points,
                                   std::span<const int> indices);

}  // namespace plywood::perception
