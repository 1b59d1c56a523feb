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
  // box's: skipped only beyond a slack of 1e-12 of the largest coordinate of all (~1000 times
  // those ulps) and a relative margin, so every count and sum is the one measuring all would give.
  constexpr double kMargin = 1.0 + 1e-9;
  std::vector<Eigen::Vector4d> boxes;  // lo x, lo y, hi x, hi y
  boxes.reserve(segments.size());
  double largest = 0.0;
  for (const LineSegment& s : segments) {
    boxes.emplace_back(std::min(s.start.x(), s.end.x()), std::min(s.start.y(), s.end.y()),
                       std::max(s.start.x(), s.end.x()), std::max(s.start.y(), s.end.y()));
    largest = std::max({largest, s.start.cwiseAbs().maxCoeff(), s.end.cwiseAbs().maxCoeff()});
  }
  const double slack_m = 1e-12 * largest;
  const auto reach_sq = [&](double d) { return (d + slack_m) * (d + slack_m) * kMargin; };
  const double max_sq = reach_sq(max_distance_m);
  for (const Eigen::Vector2d& p : points) {
    double best = std::numeric_limits<double>::infinity();
    double limit_sq = max_sq;  // beyond it a segment changes nothing counted
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const Eigen::Vector4d& box = boxes[i];
      const double dx = std::max({box[0] - p.x(), p.x() - box[2], 0.0});
      const double dy = std::max({box[1] - p.y(), p.y() - box[3], 0.0});
      if (dx * dx + dy * dy > limit_sq) continue;
      const double d = segments[i].SegmentDistance(p);
      if (d < best) {
        best = d;
        limit_sq = std::min(max_sq, reach_sq(best));
      }
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
