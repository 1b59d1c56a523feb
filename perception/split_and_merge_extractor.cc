#include "perception/split_and_merge_extractor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace plywood::perception {
namespace {

double ChordDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = b - a;
  const double length = d.norm();
  if (length < 1e-12) return (p - a).norm();
  return std::abs(d.x() * (p.y() - a.y()) - d.y() * (p.x() - a.x())) / length;
}

}  // namespace

const char* ToString(LineFitMethod method) {
  return method == LineFitMethod::kModal ? "modal" : "tls";
}

LineFitMethod ParseLineFitMethod(const std::string& text) {
  if (text == "tls") return LineFitMethod::kTotalLeastSquares;
  if (text == "modal") return LineFitMethod::kModal;
  throw std::invalid_argument("expected tls or modal, got '" + text + "'");
}

void SplitAndMergeOptions::Validate() const {
  breakpoints.Validate();
  if (!(split_threshold_m > 0.0)) {
    throw std::invalid_argument("split_threshold_m: must be > 0, got " +
                                std::to_string(split_threshold_m));
  }
  modal.Validate();
  if (filter.min_points < 2) {
    throw std::invalid_argument("min_points: must be >= 2, got " +
                                std::to_string(filter.min_points));
  }
  if (!(filter.min_length_m >= 0.0)) {
    throw std::invalid_argument("min_length_m: must be >= 0");
  }
}

SplitAndMergeExtractor::SplitAndMergeExtractor(const SplitAndMergeOptions& options)
    : options_(options) {
  options_.Validate();
}

std::vector<LineSegment> SplitAndMergeExtractor::Extract(const ScanPoints& scan) const {
  std::vector<LineSegment> out;
  const auto& p = scan.points;
  const double threshold = options_.split_threshold_m;
  const int min_points = std::max(2, options_.filter.min_points);
  const auto fit = [&](std::span<const int> indices) {
    return options_.fit == LineFitMethod::kModal ? FitSegmentModal(p, indices, options_.modal)
                                                 : FitSegmentTls(p, indices);
  };
  std::vector<std::vector<int>> pieces;
  std::vector<std::pair<int, int>> stack;
  for (std::vector<int>& group : SplitAtBreakpoints(scan, options_.breakpoints)) {
    if (static_cast<int>(group.size()) < min_points) continue;
    // Iterative end-point fit over positions [lo, hi] of `group` (inclusive).
    pieces.clear();
    stack.assign(1, {0, static_cast<int>(group.size()) - 1});
    std::vector<char> outlier(group.size(), 0);
    while (!stack.empty()) {
      auto [lo, hi] = stack.back();
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
        for (int k = lo; k <= hi; ++k)
          if (!outlier[k]) piece.push_back(group[k]);
        pieces.push_back(std::move(piece));
        continue;
      }
      if (options_.skip_single_outliers) {
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
    std::vector<LineSegment> lines;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      if (k + 1 < pieces.size() && pieces[k].back() == pieces[k + 1].front() &&
          pieces[k].size() >= 3 && pieces[k + 1].size() >= 3) {
        const int shared = pieces[k].back();
        pieces[k].pop_back();
        pieces[k + 1].erase(pieces[k + 1].begin());
        const LineSegment left = FitSegmentTls(p, pieces[k]);
        const LineSegment right = FitSegmentTls(p, pieces[k + 1]);
        if (std::abs(left.SignedLineDistance(p[shared])) <=
            std::abs(right.SignedLineDistance(p[shared]))) {
          pieces[k].push_back(shared);
        } else {
          pieces[k + 1].insert(pieces[k + 1].begin(), shared);
        }
      }
    }
    // Merge neighbours whose union is still one line (the end-point fit over-splits when the
    // chord of a long group passes far from its middle).
    std::vector<std::vector<int>> merged;
    for (auto& piece : pieces) {
      if (piece.size() < 2) continue;
      if (!merged.empty()) {
        std::vector<int> both = merged.back();
        both.insert(both.end(), piece.begin(), piece.end());
        LineMoments m;
        for (int i : both) m.Add(p[i]);
        double alpha = 0, r = 0;
        m.Fit(&alpha, &r);
        if (MaxLineDistance(p, both, alpha, r) <= threshold) {
          merged.back() = std::move(both);
          continue;
        }
      }
      merged.push_back(std::move(piece));
    }
    for (const auto& piece : merged) {
      if (static_cast<int>(piece.size()) < min_points) continue;
      LineSegment s = fit(piece);
      if (s.LengthM() < options_.filter.min_length_m) continue;
      out.push_back(s);
    }
  }
  return out;
}

}  // namespace plywood::perception
