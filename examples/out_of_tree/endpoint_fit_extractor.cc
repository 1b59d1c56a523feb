#include "endpoint_fit_extractor.h"

#include <Eigen/Core>
#include <cmath>
#include <utility>

namespace lab {
namespace {

using plywood::perception::LineSegment;

// Total-least-squares line through points[first..last]: the normal angle minimising the sum of
// squared distances is 0.5 atan2(-2 s_xy, s_yy - s_xx) about the centroid.
LineSegment FitLine(const std::vector<Eigen::Vector2d>& points, int first, int last) {
  const int count = last - first + 1;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (int i = first; i <= last; ++i) centroid += points[i];
  centroid /= count;
  double s_xx = 0.0, s_yy = 0.0, s_xy = 0.0;
  for (int i = first; i <= last; ++i) {
    const Eigen::Vector2d d = points[i] - centroid;
    s_xx += d.x() * d.x();
    s_yy += d.y() * d.y();
    s_xy += d.x() * d.y();
  }
  const double alpha = 0.5 * std::atan2(-2.0 * s_xy, s_yy - s_xx);
  LineSegment line;
  plywood::perception::CanonicalNormalForm(
      alpha, centroid.dot(Eigen::Vector2d(std::cos(alpha), std::sin(alpha))), &line.alpha_rad,
      &line.r_m);
  const Eigen::Vector2d normal = line.Normal();
  const auto project = [&](const Eigen::Vector2d& p) {
    return p - (p.dot(normal) - line.r_m) * normal;
  };
  line.start = project(points[first]);
  line.end = project(points[last]);
  line.num_points = count;
  line.first_index = first;
  line.last_index = last;
  return line;
}

// Distance of p from the line through a and b (from a when they coincide).
double ChordDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length = ab.norm();
  if (length < 1e-12) return (p - a).norm();
  return std::abs(ab.x() * (p.y() - a.y()) - ab.y() * (p.x() - a.x())) / length;
}

}  // namespace

std::vector<LineSegment> EndpointFitExtractor::Extract(
    const plywood::perception::ScanPoints& scan) const {
  const std::vector<Eigen::Vector2d>& points = scan.points;
  std::vector<LineSegment> lines;
  const int n = static_cast<int>(points.size());
  int run_start = 0;
  for (int i = 1; i <= n; ++i) {
    if (i < n && (points[i] - points[i - 1]).norm() <= options_.max_gap_m) continue;
    // points[run_start .. i-1] is one run: split it until every piece is straight enough.
    std::vector<std::pair<int, int>> pending{{run_start, i - 1}};
    std::vector<std::pair<int, int>> pieces;
    while (!pending.empty()) {
      const auto [first, last] = pending.back();
      pending.pop_back();
      if (last - first + 1 < options_.min_points) continue;
      int farthest = first;
      double farthest_distance = 0.0;
      for (int k = first + 1; k < last; ++k) {
        const double d = ChordDistance(points[k], points[first], points[last]);
        if (d > farthest_distance) farthest_distance = d, farthest = k;
      }
      if (farthest_distance > options_.split_distance_m) {
        pending.emplace_back(farthest + 1, last);
        pending.emplace_back(first, farthest);
      } else {
        pieces.emplace_back(first, last);
      }
    }
    for (const auto& [first, last] : pieces) {
      const LineSegment line = FitLine(points, first, last);
      if (line.LengthM() >= options_.min_length_m) lines.push_back(line);
    }
    run_start = i;
  }
  return lines;
}

}  // namespace lab
