#include "perception/lines/split_and_merge_extractor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "msgs/shortest_number.h"

namespace plywood::perception {
namespace {

double ChordDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = b - a;
  const double length = d.norm();
  if (length < 1e-12) return (p - a).norm();
  return std::abs(d.x() * (p.y() - a.y()) - d.y() * (p.x() - a.x())) / length;
}

// Distance of `q` from the total-least-squares line of `moments`.
double FitDistance(const LineMoments& moments, const Eigen::Vector2d& q) {
  double alpha = 0.0, r = 0.0;
  moments.Fit(&alpha, &r);
  return std::abs(q.x() * std::cos(alpha) + q.y() * std::sin(alpha) - r);
}

// The end-point fit splits a corner at the point farthest from the chord, so a few points of one
// wall next to the corner can stay with the other when they are within split_threshold_m of it.
// Moves boundary points between neighbouring pieces while one fits the other line better (each
// line fitted without that point): noise-free corners come out exact.
// `left_moments` and `right_moments` are the pieces' moments, kept up to date.
void MoveCornerPoints(std::span<const Eigen::Vector2d> p, std::vector<int>* left,
                      std::vector<int>* right, LineMoments& left_moments,
                      LineMoments& right_moments) {
  if (left->size() < 4 || right->size() < 4) return;
  if (left->back() == right->front()) {  // a split point both pieces kept: one gives it up
    const Eigen::Vector2d& shared = p[left->back()];
    LineMoments left_without = left_moments, right_without = right_moments;
    left_without.Remove(shared);
    right_without.Remove(shared);
    if (FitDistance(left_without, shared) <= FitDistance(right_without, shared)) {
      right_moments = right_without;
      right->erase(right->begin());
    } else {
      left_moments = left_without;
      left->pop_back();
    }
  }
  constexpr int kMaxMoves = 32;
  for (int move = 0; move < kMaxMoves; ++move) {
    if (left->size() < 4 || right->size() < 4) return;
    const Eigen::Vector2d& last = p[left->back()];
    const Eigen::Vector2d& first = p[right->front()];
    LineMoments left_without = left_moments, right_without = right_moments;
    left_without.Remove(last);
    right_without.Remove(first);
    if (FitDistance(right_moments, last) < FitDistance(left_without, last)) {
      left_moments = left_without;
      right_moments.Add(last);
      right->insert(right->begin(), left->back());
      left->pop_back();
    } else if (FitDistance(left_moments, first) < FitDistance(right_without, first)) {
      right_moments = right_without;
      left_moments.Add(first);
      left->push_back(right->front());
      right->erase(right->begin());
    } else {
      return;
    }
  }
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
                                msgs::ShortestNumber(split_threshold_m));
  }
  modal.Validate();
  round_objects.Validate();
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
  std::vector<int> position(p.size(), -1);  // of each point in its breakpoint group
  std::vector<LineMoments> moments;         // of each merged piece
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
        // Bounds passed in: clang 14 cannot capture structured bindings (a C++20 addition).
        const auto near_chord = [&](int k, int first, int last) {
          return k < first || k > last || ChordDistance(a, b, p[group[k]]) < 0.5 * threshold;
        };
        if (worst - 1 >= lo && worst + 1 <= hi && near_chord(worst - 1, lo, hi) &&
            near_chord(worst + 1, lo, hi)) {
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
    // Round objects first: the merge below can join a column's chords into one line again (the
    // union's own fit is closer to the arc than the chord the split tested).
    RemoveRoundObjects(p, options_.breakpoints.sigma_m, options_.round_objects, &pieces);
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
    RemoveRoundObjects(p, options_.breakpoints.sigma_m, options_.round_objects, &merged);
    // Neighbouring pieces (no dropped run between them) share a corner.
    for (std::size_t k = 0; k < group.size(); ++k) position[group[k]] = static_cast<int>(k);
    const auto neighbours = [&](const std::vector<int>& left, const std::vector<int>& right) {
      const int gap = position[right.front()] - position[left.back()];
      return gap >= 0 && gap <= 2;  // 0: a shared split point, 2: a skipped single outlier
    };
    moments.assign(merged.size(), LineMoments());
    for (std::size_t k = 0; k < merged.size(); ++k)
      for (int i : merged[k]) moments[k].Add(p[i]);
    for (std::size_t k = 0; k + 1 < merged.size(); ++k) {
      if (neighbours(merged[k], merged[k + 1])) {
        MoveCornerPoints(p, &merged[k], &merged[k + 1], moments[k], moments[k + 1]);
      }
    }
    // A closed scan without breakpoints is one group that starts and ends at the same corner.
    if (scan.closed && group.size() == p.size() && merged.size() >= 3 &&
        position[merged.front().front()] == 0 &&
        position[merged.back().back()] == static_cast<int>(group.size()) - 1) {
      MoveCornerPoints(p, &merged.back(), &merged.front(), moments.back(), moments.front());
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
