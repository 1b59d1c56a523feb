#include "perception/lines/tls_line_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"

namespace plywood::perception {
namespace {

// Endpoints, covariance and count for a line through points[indices].
void Finish(std::span<const Eigen::Vector2d> points, std::span<const int> indices, double rss,
            LineSegment* s) {
  const Eigen::Vector2d n = s->Normal();
  const Eigen::Vector2d d(-n.y(), n.x());
  double t_min = std::numeric_limits<double>::infinity(), t_max = -t_min, t_sum = 0.0;
  for (int i : indices) {
    const double t = points[i].dot(d);
    t_min = std::min(t_min, t);
    t_max = std::max(t_max, t);
    t_sum += t;
  }
  const double count = static_cast<double>(indices.size());
  const double t_mean = t_sum / count;
  double spread = 0.0;
  for (int i : indices) spread += std::pow(points[i].dot(d) - t_mean, 2);
  s->start = s->r_m * n + t_min * d;
  s->end = s->r_m * n + t_max * d;
  // Keep the scan order: start at the first point's end.
  if (points[indices.front()].dot(d) > points[indices.back()].dot(d)) std::swap(s->start, s->end);
  s->num_points = static_cast<int>(indices.size());
  s->first_index = indices.front();
  s->last_index = indices.back();
  // Point variance from the residuals; var(alpha) = sigma^2 / sum (t - t_mean)^2, and
  // r = c . n(alpha) so dr/dalpha = t_mean (the centroid's coordinate along the line).
  const double sigma_sq = count > 2 ? rss / (count - 2.0) : 0.0;
  const double var_alpha = sigma_sq / std::max(spread, 1e-12);
  s->covariance << var_alpha, t_mean * var_alpha, t_mean * var_alpha,
      sigma_sq / count + t_mean * t_mean * var_alpha;
}

}  // namespace

void LineMoments::Fit(double* alpha_rad, double* r_m, double* rss_m2) const {
  FitWithNormal(alpha_rad, r_m, nullptr, nullptr, rss_m2);
}

void LineMoments::FitWithNormal(double* alpha_rad, double* r_m, double* cos_alpha,
                                double* sin_alpha, double* rss_m2) const {
  const double n = n_;
  const double mx = sx_ / n, my = sy_ / n;
  const double cxx = sxx_ - n * mx * mx, cyy = syy_ - n * my * my, cxy = sxy_ - n * mx * my;
  // The normal is the eigenvector of the scatter matrix with the smaller eigenvalue.
  const double a = 0.5 * std::atan2(-2.0 * cxy, cyy - cxx);
  const double c = std::cos(a), s = std::sin(a);
  const double signed_r = (mx + origin_.x()) * c + (my + origin_.y()) * s;
  CanonicalNormalForm(a, signed_r, alpha_rad, r_m);
  if (cos_alpha == nullptr || sin_alpha == nullptr) {
    // Fit(): the caller needs no normal.
  } else if (*alpha_rad == a) {  // |a| <= pi / 2 and r >= 0: alpha is a itself (NaN never equals)
    *cos_alpha = c;
    *sin_alpha = s;
  } else {
    *cos_alpha = std::cos(*alpha_rad);
    *sin_alpha = std::sin(*alpha_rad);
  }
  if (rss_m2 != nullptr) *rss_m2 = std::max(0.0, c * c * cxx + 2.0 * c * s * cxy + s * s * cyy);
}

double LineMoments::FitDistance(const Eigen::Vector2d& q) const {
  double alpha = 0.0, r = 0.0, c = 0.0, s = 0.0;
  FitWithNormal(&alpha, &r, &c, &s);
  return std::abs(q.dot(Eigen::Vector2d(c, s)) - r);
}

LineSegment FitSegmentTls(std::span<const Eigen::Vector2d> points, std::span<const int> indices) {
  LineMoments moments;
  for (int i : indices) moments.Add(points[i]);
  LineSegment s;
  double rss = 0.0;
  moments.Fit(&s.alpha_rad, &s.r_m, &rss);
  Finish(points, indices, rss, &s);
  return s;
}

LineSegment FitSegmentTrimmed(std::span<const Eigen::Vector2d> points, std::vector<int> indices,
                              double trim_sigmas, int rounds) {
  LineSegment s = FitSegmentTls(points, indices);
  std::vector<double> residual;
  for (int round = 0; round < rounds; ++round) {
    residual.clear();
    for (int i : indices) residual.push_back(std::abs(s.SignedLineDistance(points[i])));
    std::vector<double> sorted = residual;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double limit = std::max(trim_sigmas * 1.4826 * sorted[sorted.size() / 2], 1e-9);
    std::vector<int> kept;
    for (std::size_t k = 0; k < indices.size(); ++k)
      if (residual[k] <= limit) kept.push_back(indices[k]);
    if (kept.size() == indices.size() || kept.size() < 2) break;
    indices = std::move(kept);
    s = FitSegmentTls(points, indices);
  }
  return s;
}

void ModalFitOptions::Validate() const {
  if (pair_step < 1) {
    throw std::invalid_argument("pair_step: must be >= 1, got " + std::to_string(pair_step));
  }
  // Each fit holds 180 / bin_deg bins: 1e-6 deg took minutes and 720 MB per segment, 1e-7 crashed
  // after 7 GB, and below 1e-7 the count overflowed to one bin, a mean of every pair, exit 0
  // (s60). No pair's direction is known to 0.05 deg (1 mm of range noise over 1 m is 0.057 deg),
  // the finest bin of seed 003's histograms too.
  if (!(bin_deg >= 0.05 && bin_deg <= 45.0)) {
    throw std::invalid_argument("bin_deg: must be in [0.05, 45], got " +
                                msgs::ShortestNumber(bin_deg));
  }
}

LineSegment FitSegmentModal(std::span<const Eigen::Vector2d> points, std::span<const int> indices,
                            const ModalFitOptions& options) {
  const int n = static_cast<int>(indices.size());
  const int step = std::min(options.pair_step, n - 1);
  if (n < 3 || step < 1) return FitSegmentTls(points, indices);
  // Directions modulo pi, so a pair's order does not matter.
  const int bins = std::max(1, static_cast<int>(std::lround(180.0 / options.bin_deg)));
  std::vector<int> histogram(bins, 0);
  std::vector<double> direction(n - step);
  std::vector<int> bin_of(n - step);
  for (int k = 0; k + step < n; ++k) {
    const Eigen::Vector2d v = points[indices[k + step]] - points[indices[k]];
    double a = std::atan2(v.y(), v.x());
    if (a < 0.0) a += std::numbers::pi;
    if (a >= std::numbers::pi) a -= std::numbers::pi;
    direction[k] = a;
    bin_of[k] = std::min(bins - 1, static_cast<int>(a / std::numbers::pi * bins));
    ++histogram[bin_of[k]];
  }
  int mode = 0, best = -1;
  for (int b = 0; b < bins; ++b) {
    const int votes = histogram[(b + bins - 1) % bins] + histogram[b] + histogram[(b + 1) % bins];
    if (votes > best) best = votes, mode = b;
  }
  // Mean direction of the inlier pairs as a doubled-angle circular mean (directions are mod pi).
  double c2 = 0.0, s2 = 0.0;
  std::vector<char> inlier(n, 0);
  for (int k = 0; k + step < n; ++k) {
    const int d = std::abs(bin_of[k] - mode);
    if (std::min(d, bins - d) > 1) continue;
    c2 += std::cos(2.0 * direction[k]);
    s2 += std::sin(2.0 * direction[k]);
    inlier[k] = inlier[k + step] = 1;
  }
  const double a = 0.5 * std::atan2(s2, c2) + std::numbers::pi / 2.0;
  const Eigen::Vector2d normal(std::cos(a), std::sin(a));
  double r_sum = 0.0;
  int r_count = 0;
  for (int k = 0; k < n; ++k) {
    if (!inlier[k]) continue;
    r_sum += points[indices[k]].dot(normal);
    ++r_count;
  }
  LineSegment s;
  CanonicalNormalForm(a, r_sum / r_count, &s.alpha_rad, &s.r_m);
  double rss = 0.0;
  for (int i : indices) rss += std::pow(s.SignedLineDistance(points[i]), 2);
  Finish(points, indices, rss, &s);
  return s;
}

double MaxLineDistance(std::span<const Eigen::Vector2d> points, std::span<const int> indices,
                       double alpha_rad, double r_m) {
  const double c = std::cos(alpha_rad), s = std::sin(alpha_rad);
  double worst = 0.0;
  for (int i : indices) {
    worst = std::max(worst, std::abs(points[i].x() * c + points[i].y() * s - r_m));
  }
  return worst;
}

bool WithinLineDistance(std::span<const Eigen::Vector2d> points, std::span<const int> indices,
                        double c, double s, double r_m, double max_distance_m) {
  // MaxLineDistance's max starts at 0 and skips NaN distances (std::max keeps its first argument),
  // so its result exceeds max_distance_m >= 0 exactly when some distance does.
  for (int i : indices) {
    if (std::abs(points[i].x() * c + points[i].y() * s - r_m) > max_distance_m) return false;
  }
  return true;
}

}  // namespace plywood::perception
