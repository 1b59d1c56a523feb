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
    const std::vector<LineSegment> lines = extractor.Extract(scan);
    result.extract_wall_s +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++result.scans;
    result.lines += static_cast<long>(lines.size());
    const RayExplanation explained = ExplainRays(scan.points, lines);
    result.rays.Add(explained);
    result.per_scan.push_back({.valid_rays = explained.rays,
                               .explained = explained.explained,
                               .lines = static_cast<int>(lines.size())});
    if (!keep_segments) continue;
    const msgs::Pose2D& X = record.X_WL;
    const double c = std::cos(X.theta_rad), s = std::sin(X.theta_rad);
    const auto to_world = [&](const Eigen::Vector2d& p) {
      return Eigen::Vector2d(X.x_m + c * p.x() - s * p.y(), X.y_m + s * p.x() + c * p.y());
    };
    for (const LineSegment& line : lines)
      result.segments_W.emplace_back(to_world(line.start), to_world(line.end));
  }
  return result;
}

}  // namespace plywood::perception
