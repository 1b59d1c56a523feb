#include "perception/lines/line_extractor.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"

namespace plywood::perception {

void BreakpointOptions::Validate() const {
  if (!(min_m > 0.0))
    throw std::invalid_argument("min_m: must be > 0, got " + msgs::ShortestNumber(min_m));
  if (!(max_m >= min_m)) {
    throw std::invalid_argument("max_m: must be >= min_m, got " + msgs::ShortestNumber(max_m));
  }
  if (!(lambda_deg > 0.0 && lambda_deg < 90.0)) {
    throw std::invalid_argument("lambda_deg: must be in (0, 90), got " +
                                msgs::ShortestNumber(lambda_deg));
  }
  if (!(sigma_m >= 0.0)) {
    throw std::invalid_argument("sigma_m: must be >= 0, got " + msgs::ShortestNumber(sigma_m));
  }
  ValidateMaxMissingBeams(max_missing_beams);
}

void ValidateMaxMissingBeams(int max_missing_beams) {
  if (max_missing_beams < 0) {
    throw std::invalid_argument("max_missing_beams: must be >= 0, got " +
                                std::to_string(max_missing_beams));
  }
}

std::vector<std::vector<int>> SplitAtBreakpoints(const ScanPoints& scan,
                                                 const BreakpointOptions& options) {
  std::vector<std::vector<int>> groups;
  const int n = static_cast<int>(scan.size());
  if (n == 0) return groups;
  const double dphi = std::abs(scan.angle_increment_rad);
  const double lambda = options.lambda_deg * std::numbers::pi / 180.0;
  const double ratio = dphi > 0.0 && lambda > dphi ? std::sin(dphi) / std::sin(lambda - dphi) : 0.0;
  // Local copies of what the test below reads for every point: the group being built is written
  // between tests, and the compiler must assume a write may change anything read through a
  // reference, so it would load each of these again for every point.
  const int* const beam_index = scan.beam_index.data();
  const double* const range_m = scan.range_m.data();
  const Eigen::Vector2d* const points = scan.points.data();
  const int beam_count = static_cast<int>(scan.beam_index.size());
  const double three_sigma_m = 3.0 * options.sigma_m, min_m = options.min_m, max_m = options.max_m;
  const int max_missing_beams = options.max_missing_beams;
  // i before j in scan order: no opening between them, and within the adaptive threshold.
  // Always inlined: the loop below asks it once per point.
  const auto near = [&](int i, int j) __attribute__((always_inline)) {
    if (OpeningBetween(scan, i, j, max_missing_beams)) return false;
    // Invalid beams may lie between neighbours: scale by the number of beam steps.
    const int beam_steps = std::abs(beam_index[j] - beam_index[i]);
    const double steps = beam_steps >= 1 && beam_steps < beam_count ? beam_steps : 1;
    const double d = std::min(range_m[i], range_m[j]) * ratio * steps + three_sigma_m;
    const double threshold = std::min(max_m, std::max(min_m, d));
    const double dx = points[i].x() - points[j].x(), dy = points[i].y() - points[j].y();
    return std::sqrt(dx * dx + dy * dy) <= threshold;  // Eigen's norm(), the same sum
  };
  // For a closed scan start at a breakpoint so no wall is cut at the seam.
  int start = 0;
  bool wrap = false;
  if (scan.closed && n > 2) {
    wrap = true;
    const auto lone = [&](int i) {
      const int before = (i + n - 1) % n, after = (i + 1) % n;
      return options.drop_lone_outliers && !near(before, i) && !near(i, after) &&
             near(before, after);
    };
    for (int i = 0; i < n; ++i) {
      if (!near((i + n - 1) % n, i) && !lone(i) && !lone((i + n - 1) % n)) {
        start = i;
        wrap = false;  // a real break exists: the seam is one of them
        break;
      }
    }
    if (wrap) {
      // One closed loop of points: cut at the sharpest corner, where a point and both its
      // neighbours lie far from the chord between the fifth neighbours on either side (a single
      // outlier has near neighbours), so no wall is cut in two.
      double sharpest = -1.0;
      const int k = std::min(5, (n - 1) / 2);
      const auto chord_distance = [&](int i, int j) {
        const Eigen::Vector2d& a = scan.points[(i + n - k) % n];
        const Eigen::Vector2d d = scan.points[(i + k) % n] - a;
        const Eigen::Vector2d q = scan.points[(j + n) % n] - a;
        return std::abs(d.x() * q.y() - d.y() * q.x()) / std::max(d.norm(), 1e-12);
      };
      for (int i = 0; i < n && k > 1; ++i) {
        const double distance =
            std::min({chord_distance(i, i - 1), chord_distance(i, i), chord_distance(i, i + 1)});
        if (distance > sharpest) sharpest = distance, start = i;
      }
    }
  }
  const bool closed_order = scan.closed && n > 2;
  // The k-th point in scan order from `start`, for 0 <= k < 2 n.
  const auto order = [&](int k) { return start + k < n ? start + k : start + k - n; };
  // near(i, i + 1) for every point in one straight pass (and near(n - 1, 0) past the seam of a
  // closed scan): the loop below asks it of neighbours in scan order (order(k) and
  // order(k + 1) are i and (i + 1) % n), and only asks near() itself after a dropped lone outlier.
  std::vector<char> near_next(n, 0);
  for (int i = 0; i + 1 < n; ++i) near_next[i] = near(i, i + 1);
  if (closed_order) near_next[n - 1] = near(n - 1, 0);
  // One scratch vector for the group being built; each group is copied out at its exact size.
  std::vector<int> current;
  current.reserve(n);
  current.push_back(order(0));
  // i = order(k) and before = order(k - 1), stepped along instead of recomputed.
  for (int k = 1, before = start, i = order(1); k < n;
       ++k, before = i, i = i + 1 == n ? 0 : i + 1) {
    const int previous = current.back();  // never empty here
    if (previous == before ? near_next[before] : near(previous, i)) {
      current.push_back(i);
      continue;
    }
    // Lone outlier: i is far from its predecessor, but the predecessor is near the next point.
    if (options.drop_lone_outliers && (k + 1 < n || closed_order)) {
      const int next = order((k + 1) % n);  // (i + 1) % n
      if (!near_next[i] && near(previous, next)) continue;
    }
    groups.emplace_back(current.begin(), current.end());
    current.clear();
    current.push_back(i);
  }
  groups.push_back(std::move(current));
  return groups;
}

std::vector<std::vector<int>> SplitRunsAlongLine(std::span<const Eigen::Vector2d> points,
                                                 std::vector<int> indices, double alpha_rad,
                                                 double max_gap_m) {
  const Eigen::Vector2d d(-std::sin(alpha_rad), std::cos(alpha_rad));
  std::vector<std::pair<double, int>> keyed;
  keyed.reserve(indices.size());
  for (int i : indices) keyed.emplace_back(points[i].dot(d), i);
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::vector<int>> runs;
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    if (k == 0 || keyed[k].first - keyed[k - 1].first > max_gap_m) runs.emplace_back();
    runs.back().push_back(keyed[k].second);
  }
  return runs;
}

std::vector<std::vector<int>> SplitRunsInScan(const ScanPoints& scan, std::vector<int> indices,
                                              double alpha_rad, double max_gap_m,
                                              int max_missing_beams) {
  const int n = static_cast<int>(scan.size());
  // Whether a and b are at most one point apart in scan order with no opening on the way.
  const auto scan_neighbours = [&](int a, int b) {
    int first = std::min(a, b), last = std::max(a, b);
    if (scan.closed && last - first > n - last + first) std::swap(first, last);  // via the seam
    const int steps = (last - first + n) % n;
    if (steps < 1 || steps > 2) return false;
    for (int k = first; k != last; k = (k + 1) % n) {
      if (OpeningBetween(scan, k, (k + 1) % n, max_missing_beams)) return false;
    }
    return true;
  };
  std::vector<std::vector<int>> runs;
  for (std::vector<int>& run :
       SplitRunsAlongLine(scan.points, std::move(indices), alpha_rad, max_gap_m)) {
    for (std::size_t k = 0; k < run.size(); ++k) {
      if (k == 0 || !scan_neighbours(run[k - 1], run[k])) runs.emplace_back();
      runs.back().push_back(run[k]);
    }
  }
  return runs;
}

}  // namespace plywood::perception
