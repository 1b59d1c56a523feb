#include "perception/lines/end_point_fit.h"

#include <cmath>
#include <utility>

#include "perception/lines/tls_line_fit.h"

namespace plywood::perception {
namespace {

double ChordDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = b - a;
  const double length = d.norm();
  if (length < 1e-12) return (p - a).norm();
  return std::abs(d.x() * (p.y() - a.y()) - d.y() * (p.x() - a.x())) / length;
}

// The total-least-squares line of points[indices] (FitSegmentTls's alpha and r, bit for bit),
// without the endpoints and covariance a distance test does not need.
LineSegment FitLine(std::span<const Eigen::Vector2d> points, std::span<const int> indices) {
  LineMoments moments;
  for (int i : indices) moments.Add(points[i]);
  LineSegment s;
  moments.Fit(&s.alpha_rad, &s.r_m);
  return s;
}

}  // namespace

std::vector<std::vector<int>> SplitByEndPointFit(std::span<const Eigen::Vector2d> p,
                                                 std::span<const int> group, double threshold_m,
                                                 bool skip_single_outliers) {
  const double threshold = threshold_m;
  if (group.size() < 2) return {};
  // Iterative end-point fit over positions [lo, hi] of `group` (inclusive).
  std::vector<std::vector<int>> pieces;
  std::vector<std::pair<int, int>> stack;
  stack.reserve(32);
  stack.push_back({0, static_cast<int>(group.size()) - 1});
  std::vector<char> outlier(group.size(), 0);
  while (!stack.empty()) {
    // Plain ints, not a structured binding: clang 14 (the fuzz build) cannot capture those.
    int lo = stack.back().first;
    int hi = stack.back().second;
    stack.pop_back();
    while (lo < hi && outlier[lo]) ++lo;
    while (hi > lo && outlier[hi]) --hi;
    if (hi - lo + 1 < 2) continue;
    const Eigen::Vector2d& a = p[group[lo]];
    const Eigen::Vector2d& b = p[group[hi]];
    const Eigen::Vector2d chord = b - a;
    const double chord_length = chord.norm();
    const Eigen::Vector2d normal = chord_length > 1e-12
                                       ? Eigen::Vector2d(-chord.y(), chord.x()) / chord_length
                                       : Eigen::Vector2d(0.0, 0.0);
    int worst = -1;
    double worst_d = threshold;
    for (int k = lo + 1; k < hi; ++k) {
      if (outlier[k]) continue;
      const double d =
          chord_length > 1e-12 ? std::abs(normal.dot(p[group[k]] - a)) : (p[group[k]] - a).norm();
      if (d > worst_d) worst_d = d, worst = k;
    }
    if (worst < 0) {
      std::vector<int> piece;
      piece.reserve(hi - lo + 1);
      for (int k = lo; k <= hi; ++k)
        if (!outlier[k]) piece.push_back(group[k]);
      pieces.push_back(std::move(piece));
      continue;
    }
    if (skip_single_outliers) {
      const auto near_chord = [&](int k) {
        return k < lo || k > hi || ChordDistance(a, b, p[group[k]]) < 0.5 * threshold;
      };
      if (worst - 1 >= lo && worst + 1 <= hi && near_chord(worst - 1) && near_chord(worst + 1)) {
        outlier[worst] = 1;
        stack.push_back({lo, hi});
        continue;
      }
    }
    // The split point belongs to both halves for now; it is assigned to one below. Push the
    // right half first so pieces come out in scan order.
    stack.push_back({worst, hi});
    stack.push_back({lo, worst});
  }
  // Pieces share their boundary point: give it to the piece whose line it fits better.
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    if (k + 1 < pieces.size() && pieces[k].back() == pieces[k + 1].front() &&
        pieces[k].size() >= 3 && pieces[k + 1].size() >= 3) {
      const int shared = pieces[k].back();
      pieces[k].pop_back();
      pieces[k + 1].erase(pieces[k + 1].begin());
      const LineSegment left = FitLine(p, pieces[k]);
      const LineSegment right = FitLine(p, pieces[k + 1]);
      if (std::abs(left.SignedLineDistance(p[shared])) <=
          std::abs(right.SignedLineDistance(p[shared]))) {
        pieces[k].push_back(shared);
      } else {
        pieces[k + 1].insert(pieces[k + 1].begin(), shared);
      }
    }
  }
  return pieces;
}

}  // namespace plywood::perception
