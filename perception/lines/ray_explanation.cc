#include "perception/lines/ray_explanation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace plywood::perception {

RayExplanation ExplainRays(std::span<const Eigen::Vector2d> points,
                           std::span<const LineSegment> segments, double max_distance_m) {
  return ExplainRays(points, segments, {}, max_distance_m);
}

RayExplanation ExplainRays(std::span<const Eigen::Vector2d> points,
                           std::span<const LineSegment> segments,
                           std::span<const CircleFeature> circles, double max_distance_m) {
  RayExplanation e;
  e.rays = static_cast<long>(points.size());
  // Each segment's box: a point's distance from the box is a lower bound of its distance from the
  // segment, so a segment whose box lies beyond the best so far (or beyond max_distance_m, where
  // no distance counts) cannot change what is counted and is not measured. Skipped only with a
  // relative margin far above rounding, so every sum is the one measuring all would give.
  constexpr double kMargin = 1.0 + 1e-9;
  std::vector<Eigen::Vector4d> boxes;  // lo x, lo y, hi x, hi y
  boxes.reserve(segments.size());
  for (const LineSegment& s : segments) {
    boxes.emplace_back(std::min(s.start.x(), s.end.x()), std::min(s.start.y(), s.end.y()),
                       std::max(s.start.x(), s.end.x()), std::max(s.start.y(), s.end.y()));
  }
  const double max_sq = max_distance_m * max_distance_m * kMargin;
  for (const Eigen::Vector2d& p : points) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const Eigen::Vector4d& box = boxes[i];
      const double dx = std::max({box[0] - p.x(), p.x() - box[2], 0.0});
      const double dy = std::max({box[1] - p.y(), p.y() - box[3], 0.0});
      const double lower_sq = dx * dx + dy * dy;
      if (lower_sq > max_sq || lower_sq > best * best * kMargin) continue;
      best = std::min(best, segments[i].SegmentDistance(p));
    }
    for (const CircleFeature& c : circles) best = std::min(best, c.RimDistance(p));
    if (best <= max_distance_m) {
      ++e.explained;
      e.sum_sq_m2 += best * best;
    }
  }
  return e;
}

}  // namespace plywood::perception
