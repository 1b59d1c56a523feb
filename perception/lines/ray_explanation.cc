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
  // no distance counts) cannot change what is counted and is not measured. SegmentDistance rounds
  // its nearest point (start + u (end - start)) by a few ulps of the segment's largest coordinate,
  // which for a ray's end 1e-7 m from a segment of metres put the distance 7e-9 relative below its
  // box's: skipped only beyond a slack of 1e-12 of that coordinate (~1000 times those ulps) and a
  // relative margin, so every count and sum is the one measuring all would give.
  constexpr double kMargin = 1.0 + 1e-9;
  constexpr double kSlackPerCoordinate = 1e-12;
  struct SegmentBox {
    double lo_x, lo_y, hi_x, hi_y, slack_m;
  };
  std::vector<SegmentBox> boxes;
  boxes.reserve(segments.size());
  for (const LineSegment& s : segments) {
    const double largest = std::max(
        {std::abs(s.start.x()), std::abs(s.start.y()), std::abs(s.end.x()), std::abs(s.end.y())});
    boxes.push_back({std::min(s.start.x(), s.end.x()), std::min(s.start.y(), s.end.y()),
                     std::max(s.start.x(), s.end.x()), std::max(s.start.y(), s.end.y()),
                     kSlackPerCoordinate * largest});
  }
  for (const Eigen::Vector2d& p : points) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const SegmentBox& box = boxes[i];
      const double dx = std::max({box.lo_x - p.x(), p.x() - box.hi_x, 0.0});
      const double dy = std::max({box.lo_y - p.y(), p.y() - box.hi_y, 0.0});
      const double lower_sq = dx * dx + dy * dy;
      const double max_reach = max_distance_m + box.slack_m, best_reach = best + box.slack_m;
      if (lower_sq > max_reach * max_reach * kMargin ||
          lower_sq > best_reach * best_reach * kMargin) {
        continue;
      }
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
