#include "viewer/polyline_thinning.h"

#include <cmath>

namespace plywood::viewer {

std::vector<Eigen::Vector2d> ThinPolyline(const std::vector<Eigen::Vector2d>& points,
                                          double tolerance_m) {
  if (points.size() <= 2) return points;
  // Points are grouped into strips of half the tolerance about a line from the strip's first
  // point; the segment drawn for a strip (first to last point) then lies within the tolerance of
  // every point in it, as long as the points move forward along the strip.
  const double half_width = 0.5 * tolerance_m;
  std::vector<Eigen::Vector2d> kept{points.front()};
  std::size_t anchor = 0;
  while (anchor + 1 < points.size()) {
    // The strip's direction: from the anchor to the first point more than the tolerance away
    // (nearer points are within the tolerance of the anchor, where the segment starts; a farther
    // point makes the direction less sensitive to the samples' jitter).
    std::size_t last = anchor + 1;
    while (last + 1 < points.size() && (points[last] - points[anchor]).norm() <= tolerance_m) {
      ++last;
    }
    const Eigen::Vector2d along = points[last] - points[anchor];
    const double length = along.norm();
    if (length > tolerance_m) {
      const Eigen::Vector2d unit = along / length;
      const Eigen::Vector2d normal(-unit.y(), unit.x());
      double reached = length;
      while (last + 1 < points.size()) {
        const Eigen::Vector2d d = points[last + 1] - points[anchor];
        const double forward = d.dot(unit);
        // Leaving the strip or turning back (the segment would not cover the way back) ends it.
        if (std::abs(d.dot(normal)) > half_width || forward < reached) break;
        reached = forward;
        ++last;
      }
    }
    kept.push_back(points[last]);
    anchor = last;
  }
  return kept;
}

}  // namespace plywood::viewer
