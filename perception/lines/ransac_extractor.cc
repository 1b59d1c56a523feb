#include "perception/lines/ransac_extractor.h"

#include <cmath>
#include <random>
#include <stdexcept>

#include "msgs/shortest_number.h"
#include "perception/lines/tls_line_fit.h"

namespace plywood::perception {

void RansacOptions::Validate() const {
  // Each iteration scores every remaining point, for every line: 2e9 iterations never finished.
  if (iterations < 1 || iterations > kMaxRansacIterations) {
    throw std::invalid_argument("iterations: must be in [1, " +
                                std::to_string(kMaxRansacIterations) + "], got " +
                                std::to_string(iterations));
  }
  if (!(distance_threshold_m > 0.0)) {
    throw std::invalid_argument("distance_threshold_m: must be > 0, got " +
                                msgs::ShortestNumber(distance_threshold_m));
  }
  if (min_inliers < 2) throw std::invalid_argument("min_inliers: must be >= 2");
  if (!(max_gap_m > 0.0)) throw std::invalid_argument("max_gap_m: must be > 0");
  if (min_points < 2) throw std::invalid_argument("min_points: must be >= 2");
  if (!(min_length_m >= 0.0)) throw std::invalid_argument("min_length_m: must be >= 0");
  if (max_lines < 1) throw std::invalid_argument("max_lines: must be >= 1");
  breakpoints.Validate();
  round_objects.Validate();
}

RansacExtractor::RansacExtractor(const RansacOptions& options) : options_(options) {
  options_.Validate();
}

std::vector<LineSegment> RansacExtractor::ExtractFromPoints(
    std::span<const Eigen::Vector2d> points, std::vector<std::vector<int>>* inliers_out) const {
  return ExtractImpl(points, nullptr, inliers_out, nullptr);
}

std::vector<LineSegment> RansacExtractor::ExtractImpl(std::span<const Eigen::Vector2d> points,
                                                      const ScanPoints* scan,
                                                      std::vector<std::vector<int>>* inliers_out,
                                                      std::vector<CircleFeature>* circles) const {
  std::vector<LineSegment> out;
  std::mt19937_64 rng(options_.seed);
  const std::vector<char> round =
      scan != nullptr
          ? RoundObjectPoints(*scan, options_.breakpoints, options_.distance_threshold_m,
                              options_.round_objects, circles)
          : std::vector<char>(points.size(), 0);
  std::vector<int> remaining;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!round[i]) remaining.push_back(static_cast<int>(i));
  const double tol = options_.distance_threshold_m;
  std::vector<int> inliers;
  std::vector<char> taken(points.size(), 0);
  for (int round = 0; round < options_.max_lines; ++round) {
    const int n = static_cast<int>(remaining.size());
    if (n < std::max(2, options_.min_inliers)) break;
    std::uniform_int_distribution<int> pick(0, n - 1);
    int best_count = 0;
    Eigen::Vector2d best_n = Eigen::Vector2d::Zero();
    double best_c = 0.0;
    for (int it = 0; it < options_.iterations; ++it) {
      const int a = pick(rng);
      int b = pick(rng);
      if (a == b) continue;
      const Eigen::Vector2d d = points[remaining[b]] - points[remaining[a]];
      const double length = d.norm();
      if (length < 1e-9) continue;
      const Eigen::Vector2d normal(-d.y() / length, d.x() / length);
      const double c = normal.dot(points[remaining[a]]);
      int count = 0;
      for (int i : remaining) count += std::abs(normal.dot(points[i]) - c) <= tol;
      if (count > best_count) best_count = count, best_n = normal, best_c = c;
    }
    if (best_count < options_.min_inliers) break;
    // Refit the consensus set, then collect the inliers of the refined line.
    LineMoments m;
    for (int i : remaining)
      if (std::abs(best_n.dot(points[i]) - best_c) <= tol) m.Add(points[i]);
    double alpha = 0, r = 0;
    m.Fit(&alpha, &r);
    const Eigen::Vector2d normal(std::cos(alpha), std::sin(alpha));
    inliers.clear();
    for (int i : remaining)
      if (std::abs(normal.dot(points[i]) - r) <= tol) inliers.push_back(i);
    if (static_cast<int>(inliers.size()) < options_.min_inliers) {
      // The refit drifted away from its consensus: fall back to the sampled line's inliers.
      inliers.clear();
      for (int i : remaining)
        if (std::abs(best_n.dot(points[i]) - best_c) <= tol) inliers.push_back(i);
    }
    const std::vector<std::vector<int>> runs =
        scan != nullptr ? SplitRunsInScan(*scan, inliers, alpha, options_.max_gap_m,
                                          options_.breakpoints.max_missing_beams)
                        : SplitRunsAlongLine(points, inliers, alpha, options_.max_gap_m);
    for (const std::vector<int>& run : runs) {
      if (static_cast<int>(run.size()) < options_.min_points) continue;
      LineSegment s = FitSegmentTrimmed(points, run);
      if (s.LengthM() < options_.min_length_m) continue;
      out.push_back(s);
      if (inliers_out != nullptr) inliers_out->push_back(run);
    }
    for (int i : inliers) taken[i] = 1;
    std::erase_if(remaining, [&](int i) { return taken[i] != 0; });
  }
  return out;
}

}  // namespace plywood::perception
