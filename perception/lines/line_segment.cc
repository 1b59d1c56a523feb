#include "perception/lines/line_segment.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "msgs/pose2d.h"

namespace plywood::perception {

Eigen::Vector2d LineSegment::Normal() const { return {std::cos(alpha_rad), std::sin(alpha_rad)}; }

double LineSegment::SegmentDistance(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d d = end - start;
  const double length_sq = d.squaredNorm();
  if (length_sq <= 0.0) return (p - start).norm();
  const double u = std::clamp((p - start).dot(d) / length_sq, 0.0, 1.0);
  return (p - (start + u * d)).norm();
}

void CanonicalNormalForm(double a_rad, double signed_r_m, double* alpha_rad, double* r_m) {
  if (signed_r_m < 0.0) {
    signed_r_m = -signed_r_m;
    a_rad += std::numbers::pi;
  }
  *alpha_rad = msgs::WrapAngle(a_rad);
  *r_m = signed_r_m;
}

double AngleDifferenceRad(double alpha_1_rad, double alpha_2_rad) {
  return std::abs(msgs::WrapAngle(alpha_1_rad - alpha_2_rad));
}

}  // namespace plywood::perception
