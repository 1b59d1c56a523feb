#include "perception/logs/log_replay.h"

#include <chrono>
#include <cmath>

namespace plywood::perception {

ReplayResult ReplayLog(const CarmenLog& log, const LineExtractor& extractor, bool keep_segments) {
  ReplayResult result;
  for (const CarmenLaserRecord& record : log.lasers) {
    const ScanPoints scan =
        MakeScanPoints(record.scan, ScanFilter::ForLog(record.scan.range_max_m));
    const auto start = std::chrono::steady_clock::now();
    ExtractedFeatures features = extractor.ExtractFeatures(scan);
    const std::vector<LineSegment>& lines = features.lines;
    result.extract_wall_s +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++result.scans;
    result.lines += static_cast<long>(lines.size());
    result.circles += static_cast<long>(features.circles.size());
    const RayExplanation explained = ExplainRays(scan.points, lines);
    const RayExplanation with_circles = ExplainRays(scan.points, lines, features.circles);
    result.rays.Add(explained);
    result.rays_with_circles.Add(with_circles);
    result.per_scan.push_back({.valid_rays = explained.rays,
                               .explained = explained.explained,
                               .explained_with_circles = with_circles.explained,
                               .lines = static_cast<int>(lines.size()),
                               .circles = static_cast<int>(features.circles.size())});
    if (!keep_segments) continue;
    const msgs::Pose2D& X = record.X_WL;
    const double c = std::cos(X.theta_rad), s = std::sin(X.theta_rad);
    const auto to_world = [&](const Eigen::Vector2d& p) {
      return Eigen::Vector2d(X.x_m + c * p.x() - s * p.y(), X.y_m + s * p.x() + c * p.y());
    };
    for (const LineSegment& line : lines)
      result.segments_W.emplace_back(to_world(line.start), to_world(line.end));
    for (CircleFeature& circle : features.circles)
      result.circles_L.emplace_back(result.scans - 1, std::move(circle));
  }
  return result;
}

}  // namespace plywood::perception
