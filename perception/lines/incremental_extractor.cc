#include "perception/lines/incremental_extractor.h"

#include <cmath>
#include <stdexcept>

#include "msgs/shortest_number.h"
#include "perception/lines/corner_refinement.h"
#include "perception/lines/mixed_pixel_ends.h"
#include "perception/lines/tls_line_fit.h"

namespace plywood::perception {

void IncrementalOptions::Validate() const {
  breakpoints.Validate();
  round_objects.Validate();
  if (!(max_distance_m > 0.0)) {
    throw std::invalid_argument("max_distance_m: must be > 0, got " +
                                msgs::ShortestNumber(max_distance_m));
  }
  if (seed_points < 2) {
    throw std::invalid_argument("seed_points: must be >= 2, got " + std::to_string(seed_points));
  }
  if (!(filter.min_length_m >= 0.0)) {
    throw std::invalid_argument("min_length_m: must be >= 0, got " +
                                msgs::ShortestNumber(filter.min_length_m));
  }
  if (filter.min_points < 2) {
    throw std::invalid_argument("min_points: must be >= 2, got " +
                                std::to_string(filter.min_points));
  }
}

IncrementalExtractor::IncrementalExtractor(const IncrementalOptions& options) : options_(options) {
  options_.Validate();
}

std::vector<LineSegment> IncrementalExtractor::Run(const ScanPoints& scan,
                                                   std::vector<CircleFeature>* circles) const {
  std::vector<LineSegment> out;
  const auto& p = scan.points;
  const double tolerance = options_.max_distance_m;
  const auto distance = [&](const LineMoments& m, const Eigen::Vector2d& q) {
    double alpha = 0, r = 0;
    m.Fit(&alpha, &r);
    return std::abs(q.x() * std::cos(alpha) + q.y() * std::sin(alpha) - r);
  };
  for (const std::vector<int>& group : SplitAtBreakpoints(scan, options_.breakpoints)) {
    const int n = static_cast<int>(group.size());
    if (n < options_.filter.min_points) continue;
    std::vector<std::vector<int>> lines;
    std::vector<LineMoments> moments;
    std::vector<int> current;
    LineMoments m;
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector2d& q = p[group[k]];
      if (static_cast<int>(current.size()) < options_.seed_points || distance(m, q) <= tolerance) {
        current.push_back(group[k]);
        m.Add(q);
        continue;
      }
      if (k + 1 < n && distance(m, p[group[k + 1]]) <= tolerance) continue;  // lone outlier
      lines.push_back(std::move(current));
      moments.push_back(m);
      current = {group[k]};
      m = LineMoments();
      m.Add(q);
    }
    lines.push_back(std::move(current));
    moments.push_back(m);
    // A line that started on a corner seed may be a continuation of its predecessor.
    std::vector<std::vector<int>> merged;
    for (auto& line : lines) {
      if (!merged.empty() && line.size() >= 2) {
        std::vector<int> both = merged.back();
        both.insert(both.end(), line.begin(), line.end());
        LineMoments u;
        for (int i : both) u.Add(p[i]);
        double alpha = 0, r = 0;
        u.Fit(&alpha, &r);
        if (MaxLineDistance(p, both, alpha, r) <= tolerance) {
          merged.back() = std::move(both);
          continue;
        }
      }
      merged.push_back(std::move(line));
    }
    RemoveRoundObjects(p, options_.breakpoints.sigma_m, options_.round_objects, &merged, circles);
    // Mixed pixels at the group's two ends (mixed_pixel_ends.h), after the round test: before it,
    // a column's run of lines loses a point and falls below min_round_points (measured: `columns`
    // precision 0.962 -> 0.947 on generator seed 1; after it 0.964).
    TrimGroupMixedPixelEnds(scan, options_.breakpoints, group, &merged);
    RefineCorners(p, group, scan.closed && n == static_cast<int>(p.size()), &merged);
    for (const auto& line : merged) {
      if (static_cast<int>(line.size()) < options_.filter.min_points) continue;
      LineSegment s = FitSegmentTrimmed(p, line);
      if (s.LengthM() < options_.filter.min_length_m) continue;
      out.push_back(s);
    }
  }
  return out;
}

}  // namespace plywood::perception
