#include "perception/lines/round_objects_of_quiet_scan.h"

#include <algorithm>
#include <cmath>

#include "perception/lines/small_round_groups.h"

namespace plywood::perception {

namespace {

// The chi-square quantile with k degrees of freedom at the upper tail probability of z standard
// normal deviates (Wilson and Hilferty's cube-root approximation; within 1 % for k >= 2).
double ChiSquareQuantile(int k, double z) {
  const double v = 2.0 / (9.0 * k);
  const double c = 1.0 - v + z * std::sqrt(v);
  return k * c * c * c;
}

// The signed angles (sensor at the origin) from the direction of the circle's centre to its
// first and last points in angle order, and the scan indices of those points.
struct AngularSpan {
  double lo = 0.0, hi = 0.0;
  int lo_index = -1, hi_index = -1;
};

AngularSpan SpanAboutCentre(const ScanPoints& scan, const CircleFeature& circle) {
  AngularSpan span;
  const Eigen::Vector2d& c = circle.centre;
  for (int i : circle.point_indices) {
    const Eigen::Vector2d& p = scan.points[i];
    const double a = std::atan2(c.x() * p.y() - c.y() * p.x(), c.dot(p));
    if (span.lo_index < 0 || a < span.lo) span.lo = a, span.lo_index = i;
    if (span.hi_index < 0 || a > span.hi) span.hi = a, span.hi_index = i;
  }
  return span;
}

// Whether the return next to scan point `end`, on the side away from the rest of the circle's
// points, is nearer than it: the object is hidden there by something in front of it.
bool HiddenPast(const ScanPoints& scan, const CircleFeature& circle, int end, double sigma_m) {
  const int n = static_cast<int>(scan.size());
  const bool first = end == circle.point_indices.front();
  if (!first && end != circle.point_indices.back()) return false;
  // Past an open scan's first or last return there is no neighbour: the wrap would read the
  // other end of the scan, half a turn away, as the return beside it (s63 review).
  if (!scan.closed && (first ? end == 0 : end == n - 1)) return false;
  const int next = first ? (end + n - 1) % n : (end + 1) % n;
  if (next == end) return false;
  if (scan.MissingBeams(first ? next : end, first ? end : next) > 0) return false;
  return scan.range_m[next] < scan.range_m[end] - 3.0 * sigma_m;
}

}  // namespace

bool SeenAsARoundObject(const ScanPoints& quiet_scan, const CircleFeature& circle, double sigma_m) {
  const int n = circle.num_points();
  if (n < 4) return false;
  // (a) The circle explains the points to their noise: a box face with one grazing return of
  // its neighbour fits a small circle only 2-3x worse than the noise (rss/sigma^2 16 for 6 points).
  const double rss_sigma2 = n * circle.rms_m * circle.rms_m / (sigma_m * sigma_m);
  if (rss_sigma2 > ChiSquareQuantile(n - 3, 2.326)) return false;  // 1 % false alarm
  // (b) A round object's nearest point lies on the line of sight to its centre, so the returns
  // show its near side around that bearing, unless something nearer hides that side.
  const AngularSpan span = SpanAboutCentre(quiet_scan, circle);
  const double width = span.hi - span.lo;
  if (!(width > 0.0)) return false;
  constexpr double kMinSideFraction = 0.25;
  if (-span.lo < kMinSideFraction * width &&
      !HiddenPast(quiet_scan, circle, span.lo_index, sigma_m))
    return false;
  if (span.hi < kMinSideFraction * width && !HiddenPast(quiet_scan, circle, span.hi_index, sigma_m))
    return false;
  return true;
}

std::vector<CircleFeature> RoundObjectsOfQuietScan(const ScanPoints& quiet_scan,
                                                   const SplitAndMergeOptions& options) {
  std::vector<CircleFeature> found =
      SplitAndMergeExtractor(options).ExtractFeatures(quiet_scan).circles;
  if (!options.round_objects.reject_round_objects) return found;
  for (CircleFeature& small : SmallRoundGroups(quiet_scan, options.breakpoints))
    found.push_back(std::move(small));
  std::erase_if(found, [&](const CircleFeature& c) {
    return !SeenAsARoundObject(quiet_scan, c, options.breakpoints.sigma_m);
  });
  return found;
}

}  // namespace plywood::perception
