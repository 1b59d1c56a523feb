#include "perception/lines/end_point_fit.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <utility>
#include <vector>

#include "perception/lines/tls_line_fit.h"

namespace plywood::perception {
namespace {

double ChordDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = b - a;
  const double length = d.norm();
  if (length < 1e-12) return (p - a).norm();
  return std::abs(d.x() * (p.y() - a.y()) - d.y() * (p.x() - a.x())) / length;
}

// GCC's vector extension (clang has it too): two doubles, SSE2 on x86-64, NEON on ARM.
using DoublePair = double __attribute__((vector_size(16)));
using BitsPair = std::int64_t __attribute__((vector_size(16)));

// The first position k in [begin, end) whose |normal . (p_k - a)| is largest and greater than
// *worst_d (updated), or -1: the farthest-point search of the end-point fit, two positions a step.
// Each lane does the scalar arithmetic of Eigen's dot, nx (x - ax) + ny (y - ay), so the
// distances and the choice are the scalar loop's bit for bit.
int FarthestFromChord(const double* xs, const double* ys, int begin, int end,
                      const Eigen::Vector2d& normal, const Eigen::Vector2d& a, double* worst_d) {
  const double nx = normal.x(), ny = normal.y(), ax = a.x(), ay = a.y();
  const DoublePair nx2 = {nx, nx}, ny2 = {ny, ny}, ax2 = {ax, ax}, ay2 = {ay, ay};
  const BitsPair magnitude = {0x7fffffffffffffff, 0x7fffffffffffffff};  // std::abs: sign bit off
  double w = *worst_d;
  DoublePair w2 = {w, w};
  int worst = -1;
  int k = begin;
  for (; k + 1 < end; k += 2) {
    DoublePair x, y;
    std::memcpy(&x, xs + k, sizeof(x));
    std::memcpy(&y, ys + k, sizeof(y));
    const DoublePair d = reinterpret_cast<DoublePair>(
        reinterpret_cast<BitsPair>(nx2 * (x - ax2) + ny2 * (y - ay2)) & magnitude);
    const BitsPair above = d > w2;
    if (above[0] | above[1]) {  // rare: a new farthest point (in order, the first of a tie wins)
      if (d[0] > w) w = d[0], worst = k;
      if (d[1] > w) w = d[1], worst = k + 1;
      w2 = DoublePair{w, w};
    }
  }
  if (k < end) {
    const double d = std::abs(nx * (xs[k] - ax) + ny * (ys[k] - ay));
    if (d > w) w = d, worst = k;
  }
  *worst_d = w;
  return worst;
}

}  // namespace

std::vector<std::vector<int>> SplitByEndPointFit(std::span<const Eigen::Vector2d> p,
                                                 std::span<const int> group, double threshold_m,
                                                 bool skip_single_outliers, int max_outlier_run) {
  const double threshold = threshold_m;
  if (group.size() < 2) return {};
  const int size = static_cast<int>(group.size());
  // The group's coordinates gathered once, in group order (x apart from y, left uninitialised
  // until written): the farthest-point search below visits every point once per recursion level,
  // two at a step, without the index lookup.
  const std::unique_ptr<double[]> xy(new double[2 * static_cast<std::size_t>(size)]);
  double* const xs = xy.get();
  double* const ys = xs + size;
  for (int k = 0; k < size; ++k) xs[k] = p[group[k]].x(), ys[k] = p[group[k]].y();
  const auto q = [&](int k) { return Eigen::Vector2d(xs[k], ys[k]); };
  // Iterative end-point fit over positions [lo, hi] of `group` (inclusive).
  std::vector<std::vector<int>> pieces;
  std::vector<std::pair<int, int>> stack;
  stack.reserve(32);
  stack.push_back({0, size - 1});
  std::vector<char> outlier(size, 0);
  bool any_outlier = false;  // until the first skipped outlier, no position needs the test
  while (!stack.empty()) {
    // Plain ints, not a structured binding: clang 14 (the fuzz build) cannot capture those.
    int lo = stack.back().first;
    int hi = stack.back().second;
    stack.pop_back();
    while (lo < hi && outlier[lo]) ++lo;
    while (hi > lo && outlier[hi]) --hi;
    if (hi - lo + 1 < 2) continue;
    const Eigen::Vector2d a = q(lo);
    const Eigen::Vector2d b = q(hi);
    const Eigen::Vector2d chord = b - a;
    const double chord_length = chord.norm();
    const Eigen::Vector2d normal = chord_length > 1e-12
                                       ? Eigen::Vector2d(-chord.y(), chord.x()) / chord_length
                                       : Eigen::Vector2d(0.0, 0.0);
    int worst = -1;
    double worst_d = threshold;
    if (chord_length > 1e-12 && !any_outlier) {
      worst = FarthestFromChord(xs, ys, lo + 1, hi, normal, a, &worst_d);
    } else {
      for (int k = lo + 1; k < hi; ++k) {
        if (outlier[k]) continue;
        const double d = chord_length > 1e-12 ? std::abs(normal.dot(q(k) - a)) : (q(k) - a).norm();
        if (d > worst_d) worst_d = d, worst = k;
      }
    }
    if (worst < 0) {
      std::vector<int> piece;
      if (!any_outlier) {
        piece.assign(group.begin() + lo, group.begin() + hi + 1);
      } else {
        piece.reserve(hi - lo + 1);
        for (int k = lo; k <= hi; ++k)
          if (!outlier[k]) piece.push_back(group[k]);
      }
      pieces.push_back(std::move(piece));
      continue;
    }
    if (skip_single_outliers) {
      const auto near_chord = [&](int k) {
        return k < lo || k > hi || ChordDistance(a, b, q(k)) < 0.5 * threshold;
      };
      if (worst - 1 >= lo && worst + 1 <= hi && near_chord(worst - 1) && near_chord(worst + 1)) {
        outlier[worst] = 1;
        any_outlier = true;
        stack.push_back({lo, hi});
        continue;
      }
    }
    if (max_outlier_run > 1) {
      // A run of 2..max_outlier_run points around the farthest one, all beyond the threshold on
      // the sensor's side (the origin), with two points on each side near the chord, the inner
      // ones not its ends: something standing in front of the surface (a table leg), whose
      // points cannot make a line of their own. The arm of a corner leaves the chord by equal
      // steps, so from two points under half the threshold it cannot pass the threshold in one;
      // a notch behind a wall is left to the split.
      const double sensor_side = -normal.dot(a);
      const auto beyond = [&](int k) {
        const double d = normal.dot(q(k) - a);
        return std::abs(d) > threshold && (d > 0.0) == (sensor_side > 0.0);
      };
      const auto near = [&](int k) { return ChordDistance(a, b, q(k)) < 0.5 * threshold; };
      int first = worst, last = worst;
      while (first - 1 > lo && last - first < max_outlier_run && beyond(first - 1)) --first;
      while (last + 1 < hi && last - first < max_outlier_run && beyond(last + 1)) ++last;
      if (beyond(worst) && last - first < max_outlier_run && first - 2 > lo && last + 2 < hi &&
          near(first - 1) && near(first - 2) && near(last + 1) && near(last + 2)) {
        for (int k = first; k <= last; ++k) outlier[k] = 1;
        any_outlier = true;
        stack.push_back({lo, hi});
        continue;
      }
    }
    // The split point belongs to both halves for now; it is assigned to one below. Push the
    // right half first so pieces come out in scan order.
    stack.push_back({worst, hi});
    stack.push_back({lo, worst});
  }
  // Pieces share their boundary point: give it to the piece whose line (fitted without it) it
  // fits better; the other piece lets it go. When the right piece lets it go, its remaining
  // points but the last are the next boundary's left line: their moments, summed on the way
  // (from the same first point, in the same order), are carried over instead of summed again.
  LineMoments carried;
  bool have_carried = false;
  for (std::size_t k = 0; k + 1 < pieces.size(); ++k) {
    std::vector<int>& left = pieces[k];
    std::vector<int>& right = pieces[k + 1];
    if (!(left.back() == right.front() && left.size() >= 3 && right.size() >= 3)) {
      have_carried = false;
      continue;
    }
    const Eigen::Vector2d& shared = p[left.back()];
    LineMoments left_moments;
    if (have_carried) {
      left_moments = carried;
    } else {
      for (std::size_t j = 0; j + 1 < left.size(); ++j) left_moments.Add(p[left[j]]);
    }
    LineMoments right_moments;
    for (std::size_t j = 1; j + 1 < right.size(); ++j) right_moments.Add(p[right[j]]);
    const LineMoments right_but_last = right_moments;
    right_moments.Add(p[right.back()]);
    if (left_moments.FitDistance(shared) <= right_moments.FitDistance(shared)) {
      right.erase(right.begin());
      carried = right_but_last;
      have_carried = true;
    } else {
      left.pop_back();
      have_carried = false;
    }
  }
  return pieces;
}

}  // namespace plywood::perception
