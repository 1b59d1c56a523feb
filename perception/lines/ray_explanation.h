#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <span>

#include "perception/lines/circle_feature.h"
#include "perception/lines/line_segment.h"

namespace plywood::perception {

// How well segments explain a scan without ground truth (plywood replay on real logs): a ray is
// explained when its endpoint lies within max_distance_m of an extracted segment -- the distance
// to the segment, not to its infinite line, so a line cannot explain points beyond its ends.
struct RayExplanation {
  long rays = 0;
  long explained = 0;
  double sum_sq_m2 = 0.0;  // squared distances of the explained rays

  double Fraction() const { return rays ? double(explained) / rays : 0.0; }
  // NaN (no number) when no ray was explained: 0 read as a perfect fit of nothing (s63).
  double RmsM() const {
    return explained ? std::sqrt(sum_sq_m2 / explained) : std::numeric_limits<double>::quiet_NaN();
  }
  void Add(const RayExplanation& o) {
    rays += o.rays;
    explained += o.explained;
    sum_sq_m2 += o.sum_sq_m2;
  }
};

RayExplanation ExplainRays(std::span<const Eigen::Vector2d> points,
                           std::span<const LineSegment> segments, double max_distance_m = 0.05);

// The same with the round objects the extractor reported: a ray is also explained when its
// endpoint lies within max_distance_m of a circle's rim (the nearest feature, line or circle,
// gives the distance).
RayExplanation ExplainRays(std::span<const Eigen::Vector2d> points,
                           std::span<const LineSegment> segments,
                           std::span<const CircleFeature> circles, double max_distance_m = 0.05);

}  // namespace plywood::perception
