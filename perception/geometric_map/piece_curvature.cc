#include "perception/geometric_map/piece_curvature.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "perception/geometric_map/option_checks.h"

namespace plywood::perception {

PieceCurvature PieceCurvature::Combined(const PieceCurvature& other) const {
  const double w1 = std::isfinite(sigma_per_m) ? 1.0 / (sigma_per_m * sigma_per_m) : 0.0;
  const double w2 =
      std::isfinite(other.sigma_per_m) ? 1.0 / (other.sigma_per_m * other.sigma_per_m) : 0.0;
  if (w1 + w2 <= 0.0) return {};
  return {(w1 * curvature_per_m + w2 * other.curvature_per_m) / (w1 + w2),
          1.0 / std::sqrt(w1 + w2)};
}

void RoundPieceOptions::Validate() const {
  RequireOption(max_object_radius_m >= 0.0 && max_object_radius_m <= 10.0, "max_object_radius_m",
                "must be in [0, 10]", max_object_radius_m);
  RequireOption(min_sigmas >= 0.0 && min_sigmas <= 100.0, "min_sigmas", "must be in [0, 100]",
                min_sigmas);
  RequireOption(noise_floor_m > 0.0 && noise_floor_m <= 1.0, "noise_floor_m", "must be in (0, 1]",
                noise_floor_m);
}

bool RoundPieceOptions::IsRound(const PieceCurvature& c) const {
  return std::isfinite(c.sigma_per_m) && c.curvature_per_m > min_sigmas * c.sigma_per_m &&
         c.curvature_per_m * max_object_radius_m >= 1.0;
}

PieceCurvature FitPieceCurvature(std::span<const Eigen::Vector2d> points,
                                 std::span<const int> indices, const Eigen::Vector2d& line_start,
                                 const Eigen::Vector2d& line_end, const Eigen::Vector2d& observer,
                                 double noise_floor_m) {
  const int n = static_cast<int>(indices.size());
  const double length = (line_end - line_start).norm();
  if (n < 3 || length <= 0.0) return {};
  const Eigen::Vector2d d = (line_end - line_start) / length;
  Eigen::Vector2d away(-d.y(), d.x());
  const Eigen::Vector2d middle = 0.5 * (line_start + line_end);
  if ((observer - middle).dot(away) > 0.0) away = -away;
  // u scaled to [-1, 1] keeps the normal equations well conditioned.
  const double half = 0.5 * length;
  Eigen::MatrixX3d a(n, 3);
  Eigen::VectorXd v(n);
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d q = points[indices[k]] - middle;
    const double t = q.dot(d) / half;
    a.row(k) << 1.0, t, t * t;
    v(k) = q.dot(away);
  }
  const Eigen::Matrix3d normal = a.transpose() * a;
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(normal);
  if (!lu.isInvertible()) return {};
  const Eigen::Vector3d coef = lu.solve(a.transpose() * v);
  const double rss = (a * coef - v).squaredNorm();
  const double sigma = std::max(noise_floor_m, n > 3 ? std::sqrt(rss / (n - 3)) : 0.0);
  const double scale = 2.0 / (half * half);  // curvature = 2c, c = coef(2) / half^2
  // v grows away from the observer: a bulge towards it has the middle smallest, c > 0.
  return {coef(2) * scale, sigma * std::sqrt(lu.inverse()(2, 2)) * scale};
}

}  // namespace plywood::perception
