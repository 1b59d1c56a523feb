#include "perception/geometric_map/scan_segmentation.h"

#include <algorithm>
#include <cmath>

#include "perception/geometric_map/option_checks.h"
#include "perception/lines/round_object_filter.h"

namespace plywood::perception {
namespace {

// Intersection of two lines in normal form; false when they are (nearly) parallel.
bool Intersect(const LineSegment& a, const LineSegment& b, Eigen::Vector2d* p) {
  Eigen::Matrix2d m;
  m << std::cos(a.alpha_rad), std::sin(a.alpha_rad), std::cos(b.alpha_rad), std::sin(b.alpha_rad);
  if (std::abs(m.determinant()) < 1e-6) return false;
  *p = m.inverse() * Eigen::Vector2d(a.r_m, b.r_m);
  return true;
}

// Iterative end-point fit of points[first..last] (inclusive): appends the pieces in order; the
// split point belongs to both pieces beside it.
void SplitAtFarthest(std::span<const Eigen::Vector2d> points, int first, int last, double r_min_m,
                     std::vector<std::pair<int, int>>* pieces) {
  const Eigen::Vector2d a = points[first], chord = points[last] - a;
  const double length = chord.norm();
  int farthest = -1;
  double worst = r_min_m;
  for (int k = first + 1; k < last; ++k) {
    const Eigen::Vector2d v = points[k] - a;
    const double d =
        length > 1e-12 ? std::abs(chord.x() * v.y() - chord.y() * v.x()) / length : v.norm();
    if (d > worst) worst = d, farthest = k;
  }
  if (farthest < 0) {
    pieces->emplace_back(first, last);
    return;
  }
  SplitAtFarthest(points, first, farthest, r_min_m, pieces);
  SplitAtFarthest(points, farthest, last, r_min_m, pieces);
}

// Per piece of one group: whether it belongs to a run of pieces that one small circle seen from
// outside explains (the line extractors' round-object test, round_object_filter.h: a column seen
// whole, its arc cut into chords). `points` relative to the observer.
std::vector<char> WholeRoundPieces(std::span<const Eigen::Vector2d> points,
                                   const std::vector<std::pair<int, int>>& pieces,
                                   const RoundPieceOptions& options) {
  std::vector<std::vector<int>> runs;
  for (const auto& [a, b] : pieces) {
    runs.emplace_back(b - a + 1);
    for (int j = a; j <= b; ++j) runs.back()[j - a] = j;
  }
  RoundObjectOptions circle;
  circle.max_round_radius_m = options.max_object_radius_m;
  circle.reject_round_objects = options.max_object_radius_m > 0.0;
  std::vector<std::vector<int>> kept = runs;
  RemoveRoundObjects(points, options.noise_floor_m, circle, &kept);
  std::vector<char> round(pieces.size(), 1);
  for (std::size_t i = 0, k = 0; i < runs.size() && k < kept.size(); ++i) {
    if (runs[i] == kept[k]) round[i] = 0, ++k;
  }
  return round;
}

Eigen::Vector2d ToMap(const msgs::Pose2D& X_WR, const Eigen::Vector2d& p_R) {
  const double c = std::cos(X_WR.theta_rad), s = std::sin(X_WR.theta_rad);
  return {X_WR.x_m + c * p_R.x() - s * p_R.y(), X_WR.y_m + s * p_R.x() + c * p_R.y()};
}

}  // namespace

void SegmentationOptions::Validate() const {
  RequireOption(dist_max_m > 0.0 && dist_max_m <= 5.0, "dist_max_m", "must be in (0, 5]",
                dist_max_m);
  RequireOption(min_line_points >= 3 && min_line_points <= 10000, "min_line_points",
                "must be in [3, 10000]", min_line_points);
  RequireOption(min_cluster_points >= 1 && min_cluster_points <= min_line_points,
                "min_cluster_points", "must be in [1, min_line_points]", min_cluster_points);
  RequireOption(max_cluster_size_m > 0.0 && max_cluster_size_m <= 10.0, "max_cluster_size_m",
                "must be in (0, 10]", max_cluster_size_m);
  RequireOption(r_min_m > 0.0 && r_min_m <= 1.0, "r_min_m", "must be in (0, 1]", r_min_m);
  modal.Validate();
  RequireOption(inlier_distance_m > 0.0 && inlier_distance_m <= 1.0, "inlier_distance_m",
                "must be in (0, 1]", inlier_distance_m);
  RequireOption(min_inlier_fraction >= 0.0 && min_inlier_fraction <= 1.0, "min_inlier_fraction",
                "must be in [0, 1]", min_inlier_fraction);
  RequireOption(max_intersection_shift_m >= 0.0 && max_intersection_shift_m <= 5.0,
                "max_intersection_shift_m", "must be in [0, 5]", max_intersection_shift_m);
  round_objects.Validate();
}

MapSegment FitMapSegment(std::span<const Eigen::Vector2d> points, std::span<const int> indices,
                         const SegmentationOptions& options, std::vector<int>* inliers_out) {
  MapSegment s;
  s.line = options.fit == LineFitMethod::kModal ? FitSegmentModal(points, indices, options.modal)
                                                : FitSegmentTls(points, indices);
  std::vector<int> inliers;
  for (int i : indices) {
    if (std::abs(s.line.SignedLineDistance(points[i])) <= options.inlier_distance_m) {
      inliers.push_back(i);
    }
  }
  s.inliers = static_cast<int>(inliers.size());
  // The modal filter's direction is the mean of pair directions inside its mode bins: with range
  // noise that truncated mean leans towards the bins' grid (tenths of a degree). Its inliers,
  // refitted by least squares, give the unbiased line.
  if (options.fit == LineFitMethod::kModal && inliers.size() >= 2) {
    s.line = FitSegmentTls(points, inliers);
  }
  s.line.num_points = static_cast<int>(indices.size());
  if (inliers_out != nullptr) *inliers_out = std::move(inliers);
  return s;
}

ScanFeatures ExtractScanFeatures(std::span<const RangePoint> points_R, int beam_count,
                                 const msgs::Pose2D& X_WR, const SegmentationOptions& options) {
  ScanFeatures features;
  const int n = static_cast<int>(points_R.size());
  if (n == 0) return features;
  // A full turn has no natural start: begin after the widest gap between neighbours.
  int start = 0;
  if (beam_count > 0 && n > 1) {
    double widest = (points_R[0].p_R - points_R[n - 1].p_R).norm();
    for (int k = 1; k < n; ++k) {
      const double gap = (points_R[k].p_R - points_R[k - 1].p_R).norm();
      if (gap > widest) widest = gap, start = k;
    }
  }
  std::vector<Eigen::Vector2d> p(n);
  for (int k = 0; k < n; ++k) p[k] = ToMap(X_WR, points_R[(start + k) % n].p_R);

  const Eigen::Vector2d observer(X_WR.x_m, X_WR.y_m);
  std::vector<Eigen::Vector2d> p_seen(n);  // relative to the observer
  for (int k = 0; k < n; ++k) p_seen[k] = p[k] - observer;
  const auto add_cluster = [&](int first, int last) {
    if (last - first + 1 < options.min_cluster_points) return;
    MapCluster c;
    for (int k = first; k <= last; ++k) c.box.extend(p[k]);
    c.points = last - first + 1;
    if (c.box.sizes().maxCoeff() <= options.max_cluster_size_m) features.clusters.push_back(c);
  };
  int first = 0;
  for (int k = 1; k <= n; ++k) {
    if (k < n && (p[k] - p[k - 1]).norm() <= options.dist_max_m) continue;
    const int last = k - 1;
    if (last - first + 1 < options.min_line_points) {
      add_cluster(first, last);
      first = k;
      continue;
    }
    std::vector<std::pair<int, int>> pieces;
    SplitAtFarthest(p, first, last, options.r_min_m, &pieces);
    const std::vector<char> on_circle = WholeRoundPieces(p_seen, pieces, options.round_objects);
    std::vector<MapSegment> lines;
    std::vector<int> line_piece;  // index into pieces of each line
    std::vector<std::pair<int, int>> round_pieces;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const auto [a, b] = pieces[i];
      if (b - a + 1 < options.min_line_points) continue;
      if (on_circle[i]) {
        round_pieces.emplace_back(a, b);
        continue;
      }
      std::vector<int> indices(b - a + 1);
      for (int j = a; j <= b; ++j) indices[j - a] = j;
      std::vector<int> inliers;
      MapSegment s = FitMapSegment(p, indices, options, &inliers);
      if (s.InlierFraction() < options.min_inlier_fraction) continue;
      s.curvature = FitPieceCurvature(p, inliers, s.line.start, s.line.end, observer,
                                      options.round_objects.noise_floor_m);
      if (options.round_objects.IsRound(s.curvature)) {
        round_pieces.emplace_back(a, b);
        continue;
      }
      lines.push_back(s);
      line_piece.push_back(static_cast<int>(i));
    }
    // Neighbouring pieces meet at their shared split point: the corner is where their lines cross.
    for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
      if (line_piece[i + 1] != line_piece[i] + 1) continue;
      const Eigen::Vector2d shared = p[pieces[line_piece[i]].second];
      Eigen::Vector2d corner;
      if (Intersect(lines[i].line, lines[i + 1].line, &corner) &&
          (corner - shared).norm() <= options.max_intersection_shift_m) {
        lines[i].line.end = corner;
        lines[i + 1].line.start = corner;
      }
    }
    if (lines.empty()) {
      add_cluster(first, last);
    } else {
      for (const auto& [a, b] : round_pieces) add_cluster(a, b);
    }
    features.segments.insert(features.segments.end(), lines.begin(), lines.end());
    first = k;
  }
  return features;
}

}  // namespace plywood::perception
