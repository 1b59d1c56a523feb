#include "perception/lines/corner_refinement.h"

#include <cmath>

#include "perception/lines/tls_line_fit.h"

namespace plywood::perception {
namespace {

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
    if (left_without.FitDistance(shared) <= right_without.FitDistance(shared)) {
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
    if (right_moments.FitDistance(last) < left_without.FitDistance(last)) {
      left_moments = left_without;
      right_moments.Add(last);
      right->insert(right->begin(), left->back());
      left->pop_back();
    } else if (left_moments.FitDistance(first) < right_without.FitDistance(first)) {
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

void RefineCorners(std::span<const Eigen::Vector2d> points, std::span<const int> group,
                   bool closed_loop, std::vector<std::vector<int>>* lines,
                   std::vector<LineMoments>* given_moments) {
  std::vector<std::vector<int>>& l = *lines;
  if (l.size() < 2) return;
  // Position in the group of each line's first and last point (lines follow the group's order).
  std::vector<int> first(l.size(), -1), last(l.size(), -1);
  std::size_t cursor = 0;
  const auto find = [&](int index) {
    while (cursor < group.size() && group[cursor] != index) ++cursor;
    return cursor < group.size() ? static_cast<int>(cursor) : -1;
  };
  for (std::size_t k = 0; k < l.size(); ++k) {
    if (l[k].empty()) continue;
    first[k] = find(l[k].front());
    last[k] = find(l[k].back());
  }
  // 0: a shared split point, 2: a skipped single outlier between them.
  const auto neighbours = [&](std::size_t left, std::size_t right) {
    const int gap = first[right] - last[left];
    return last[left] >= 0 && first[right] >= 0 && gap >= 0 && gap <= 2;
  };
  std::vector<LineMoments> own_moments;
  if (given_moments == nullptr) {
    own_moments.resize(l.size());
    for (std::size_t k = 0; k < l.size(); ++k)
      for (int i : l[k]) own_moments[k].Add(points[i]);
  }
  std::vector<LineMoments>& moments = given_moments != nullptr ? *given_moments : own_moments;
  for (std::size_t k = 0; k + 1 < l.size(); ++k) {
    if (neighbours(k, k + 1)) {
      MoveCornerPoints(points, &l[k], &l[k + 1], moments[k], moments[k + 1]);
    }
  }
  if (closed_loop && l.size() >= 3 && first.front() == 0 &&
      last.back() == static_cast<int>(group.size()) - 1) {
    MoveCornerPoints(points, &l.back(), &l.front(), moments.back(), moments.front());
  }
}

}  // namespace plywood::perception
