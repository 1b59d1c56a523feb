#include "perception/circle_fit.h"

#include <Eigen/Dense>
#include <cmath>

namespace plywood::perception {
namespace {

// Geometric residual statistics of `points[indices]` about (centre, radius).
void Residuals(std::span<const Eigen::Vector2d> points, std::span<const int> indices,
               CircleFit* fit) {
  fit->rss_m2 = 0.0;
  fit->max_residual_m = 0.0;
  for (int i : indices) {
    const double e = (points[i] - fit->centre).norm() - fit->radius_m;
    fit->rss_m2 += e * e;
    fit->max_residual_m = std::max(fit->max_residual_m, std::abs(e));
  }
}

}  // namespace

std::optional<CircleFit> FitCircle(std::span<const Eigen::Vector2d> points,
                                   std::span<const int> indices) {
  const int n = static_cast<int>(indices.size());
  if (n < 3) return std::nullopt;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (int i : indices) mean += points[i];
  mean /= n;
  // Kasa: minimise sum (u^2 + v^2 + D u + E v + F)^2 over (D, E, F), (u, v) = p - mean.
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  double scale = 0.0;
  for (int i : indices) scale += (points[i] - mean).squaredNorm();
  if (!(scale > 0.0)) return std::nullopt;
  scale = std::sqrt(scale / n);  // work in units of the points' spread
  for (int i : indices) {
    const Eigen::Vector2d q = (points[i] - mean) / scale;
    const Eigen::Vector3d row(q.x(), q.y(), 1.0);
    normal += row * row.transpose();
    rhs -= row * q.squaredNorm();
  }
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(normal);
  // Collinear points make the system rank 2: no finite circle.
  if (lu.rank() < 3) return std::nullopt;
  const Eigen::Vector3d def = lu.solve(rhs);
  Eigen::Vector2d centre(-0.5 * def(0), -0.5 * def(1));
  const double radius_sq = centre.squaredNorm() - def(2);
  if (!(radius_sq > 0.0)) return std::nullopt;
  CircleFit fit;
  fit.centre = mean + scale * centre;
  fit.radius_m = scale * std::sqrt(radius_sq);

  // Gauss-Newton on e_i = |p_i - c| - R over (c_x, c_y, R).
  for (int iteration = 0; iteration < 10; ++iteration) {
    Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
    Eigen::Vector3d jte = Eigen::Vector3d::Zero();
    for (int i : indices) {
      const Eigen::Vector2d d = points[i] - fit.centre;
      const double length = d.norm();
      if (length < 1e-12) continue;
      const Eigen::Vector3d j(-d.x() / length, -d.y() / length, -1.0);
      const double e = length - fit.radius_m;
      jtj += j * j.transpose();
      jte += j * e;
    }
    const Eigen::FullPivLU<Eigen::Matrix3d> step_lu(jtj);
    if (step_lu.rank() < 3) break;
    const Eigen::Vector3d step = -step_lu.solve(jte);
    if (!step.allFinite()) break;
    fit.centre += step.head<2>();
    fit.radius_m += step(2);
    if (step.norm() < 1e-12 * (1.0 + fit.radius_m)) break;
  }
  if (!(fit.radius_m > 0.0) || !fit.centre.allFinite()) return std::nullopt;
  Residuals(points, indices, &fit);
  return fit;
}

}  // namespace plywood::perception
