#include "perception/lines/mixed_pixel_ends.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace plywood::perception {
namespace {

constexpr double kMixedPixelSigmas = 3.0;

// Whether line[end] (end is 0 or the last index) is a mixed pixel; `outer` is its neighbour in
// scan order past the group's break.
bool IsMixedPixelEnd(const ScanPoints& scan, const BreakpointOptions& breakpoints,
                     const std::vector<int>& line, int end, int outer) {
  const int count = static_cast<int>(line.size());
  const int e = line[end];
  const bool opening = end == 0 ? scan.MissingBeams(outer, e) > 0 : scan.MissingBeams(e, outer) > 0;
  // The offset from the rest's total-least-squares line.
  const int m = count - 1;
  const int first = end == 0 ? 1 : 0;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (int k = first; k < first + m; ++k) mean += scan.points[line[k]];
  mean /= m;
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
  for (int k = first; k < first + m; ++k) {
    const Eigen::Vector2d d = scan.points[line[k]] - mean;
    sxx += d.x() * d.x(), syy += d.y() * d.y(), sxy += d.x() * d.y();
  }
  const double theta = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  const Eigen::Vector2d along(std::cos(theta), std::sin(theta));
  const Eigen::Vector2d normal(-along.y(), along.x());
  const double spread_m2 = sxx + syy -
                           (normal.x() * normal.x() * sxx + normal.y() * normal.y() * syy +
                            2.0 * normal.x() * normal.y() * sxy);
  if (!(spread_m2 > 0.0)) return false;
  const Eigen::Vector2d& p = scan.points[e];
  const double offset_m = normal.dot(p - mean);
  const double t = along.dot(p - mean);
  const double sigma_m = breakpoints.sigma_m * std::sqrt(1.0 + 1.0 / m + t * t / spread_m2);
  // Off the line beyond the prediction interval; or beyond the noise alone (the rest's line is
  // ill-determined) and farther from the inner neighbour along the beam than a surface seen at
  // incidence lambda or better moves between the two beams: Borges & Aldon's breakpoint distance
  // r sin(dphi) / sin(lambda - dphi) + 3 sigma, without the floor the group test uses.
  bool off = std::abs(offset_m) > kMixedPixelSigmas * sigma_m;
  if (!off && std::abs(offset_m) > kMixedPixelSigmas * breakpoints.sigma_m) {
    const int inner = line[end == 0 ? 1 : count - 2];
    const double dphi = std::abs(scan.angle_increment_rad);
    const double lambda = breakpoints.lambda_deg * std::numbers::pi / 180.0;
    if (dphi > 0.0 && lambda > dphi) {
      const int steps = std::max(1, std::abs(scan.beam_index[e] - scan.beam_index[inner]));
      const double max_jump_m = std::min(scan.range_m[e], scan.range_m[inner]) * std::sin(dphi) /
                                    std::sin(lambda - dphi) * steps +
                                3.0 * breakpoints.sigma_m;
      off = std::abs(scan.range_m[e] - scan.range_m[inner]) > max_jump_m;
    }
  }
  if (!off) return false;
  // Towards the surface past the break: away from the sensor (the origin) past an opening,
  // else on the outer neighbour's side of the line and no farther from it.
  if (opening) return (normal.dot(mean) > 0.0) == (offset_m > 0.0);
  const double outer_offset_m = normal.dot(scan.points[outer] - mean);
  return (outer_offset_m > 0.0) == (offset_m > 0.0) &&
         std::abs(outer_offset_m) >= std::abs(offset_m);
}

}  // namespace

void TrimMixedPixelEnds(const ScanPoints& scan, const BreakpointOptions& breakpoints,
                        bool front_is_group_end, bool back_is_group_end, std::vector<int>* line) {
  const int n = static_cast<int>(scan.size());
  if (!scan.HasScanOrder() || n < 2) return;
  if (back_is_group_end && line->size() >= 3) {
    const int last = line->back();
    const int outer = last + 1 < n ? last + 1 : (scan.closed ? 0 : -1);
    if (outer >= 0 && outer != line->front() &&
        IsMixedPixelEnd(scan, breakpoints, *line, static_cast<int>(line->size()) - 1, outer)) {
      line->pop_back();
    }
  }
  if (front_is_group_end && line->size() >= 3) {
    const int first = line->front();
    const int outer = first > 0 ? first - 1 : (scan.closed ? n - 1 : -1);
    if (outer >= 0 && outer != line->back() &&
        IsMixedPixelEnd(scan, breakpoints, *line, 0, outer)) {
      line->erase(line->begin());
    }
  }
}

std::vector<int> TrimGroupMixedPixelEnds(const ScanPoints& scan,
                                         const BreakpointOptions& breakpoints,
                                         std::span<const int> group,
                                         std::vector<std::vector<int>>* lines) {
  std::vector<int> dropped;
  std::vector<std::vector<int>>& l = *lines;
  if (l.empty() || group.empty()) return dropped;
  if (scan.closed && group.size() == scan.size()) return dropped;
  const bool front_end = !l.front().empty() && l.front().front() == group.front();
  const bool back_end = !l.back().empty() && l.back().back() == group.back();
  const auto trim = [&](std::vector<int>* line, bool front, bool back) {
    const int first = line->empty() ? -1 : line->front(), last = line->empty() ? -1 : line->back();
    TrimMixedPixelEnds(scan, breakpoints, front, back, line);
    if (line->empty() || line->front() != first) dropped.push_back(first);
    if (line->empty() || line->back() != last) dropped.push_back(last);
  };
  if (l.size() == 1) {
    trim(&l.front(), front_end, back_end);
  } else {
    trim(&l.front(), front_end, false);
    trim(&l.back(), false, back_end);
  }
  return dropped;
}

}  // namespace plywood::perception
