#include "perception/lines/ray_explanation.h"

#include <cmath>
#include <limits>

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
  for (const Eigen::Vector2d& p : points) {
    double best = std::numeric_limits<double>::infinity();
    for (const LineSegment& s : segments) best = std::min(best, s.SegmentDistance(p));
    for (const CircleFeature& c : circles) best = std::min(best, c.RimDistance(p));
    if (best <= max_distance_m) {
      ++e.explained;
      e.sum_sq_m2 += best * best;
    }
  }
  return e;
}

}  // namespace plywood::perception
