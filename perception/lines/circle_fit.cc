#include "perception/lines/circle_fit.h"

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
  // Scalar sums (the symmetric 3 x 3 system) keep this cheap: it runs on many candidate runs.
  double sxx = 0, sxy = 0, syy = 0, sx = 0, sy = 0, sxz = 0, syz = 0, sz = 0;
  for (int i : indices) {
    const Eigen::Vector2d q = (points[i] - mean) / scale;
    const double z = q.squaredNorm();
    sxx += q.x() * q.x(), sxy += q.x() * q.y(), syy += q.y() * q.y();
    sx += q.x(), sy += q.y();
    sxz += q.x() * z, syz += q.y() * z, sz += z;
  }
  normal << sxx, sxy, sx, sxy, syy, sy, sx, sy, static_cast<double>(n);
  rhs << -sxz, -syz, -sz;
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
  // The algebraic start is exact for exact points and close for noisy ones: a few steps do.
  constexpr int kMaxIterations = 4;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    double a = 0, b = 0, c = 0, d2 = 0, e2 = 0, f = 0, g = 0, h = 0, k = 0;
    for (int i : indices) {
      const Eigen::Vector2d d = points[i] - fit.centre;
      const double length = d.norm();
      if (length < 1e-12) continue;
      const double jx = -d.x() / length, jy = -d.y() / length;  // and -1 for the radius
      const double e = length - fit.radius_m;
      a += jx * jx, b += jx * jy, c -= jx, d2 += jy * jy, e2 -= jy, f += 1.0;
      g += jx * e, h += jy * e, k -= e;
    }
    Eigen::Matrix3d jtj;
    jtj << a, b, c, b, d2, e2, c, e2, f;
    const Eigen::Vector3d jte(g, h, k);
    const Eigen::LDLT<Eigen::Matrix3d> step_ldlt(jtj);  // J^T J: symmetric positive semi-definite
    if (step_ldlt.info() != Eigen::Success || !(step_ldlt.vectorD().minCoeff() > 1e-12)) break;
    const Eigen::Vector3d step = -step_ldlt.solve(jte);
    if (!step.allFinite()) break;
    fit.centre += step.head<2>();
    fit.radius_m += step(2);
    if (step.norm() < 1e-7) break;  // converges quadratically near an exact fit: ~1e-14 m then
  }
  if (!(fit.radius_m > 0.0) || !fit.centre.allFinite()) return std::nullopt;
  Residuals(points, indices, &fit);
  return fit;
}

}  // namespace plywood::perception
