#include "perception/geometric_map/geometric_mapper.h"

#include <cmath>
#include <numbers>

namespace plywood::perception {

void GeometricMapOptions::Validate() const {
  fusion.Validate();
  histograms.Validate();
  frame.Validate();
  correction.Validate();
  segmentation.Validate();
  aggregation.Validate();
}

GeometricMapper::GeometricMapper(const GeometricMapOptions& options)
    : options_((options.Validate(), options)),
      corrector_(options.histograms, options.correction),
      map_(options.aggregation) {}

msgs::Pose2D GeometricMapper::AddScan(const msgs::LaserScan& ir, const msgs::RangeRing* sonar,
                                      const msgs::Pose2D& X_OR) {
  const std::vector<RangePoint> points = FuseRanges(ir, sonar, options_.fusion);
  points_seen_ += static_cast<long>(points.size());
  for (const RangePoint& p : points) sonar_points_ += p.from_sonar;
  const msgs::Pose2D X_WR = corrector_.Correct(X_OR, points);

  const bool full_turn =
      std::abs(std::abs(ir.angle_increment_rad) * static_cast<double>(ir.ranges_m.size()) -
               2.0 * std::numbers::pi) < 1e-6;
  const ScanFeatures features = ExtractScanFeatures(
      points, full_turn ? static_cast<int>(ir.ranges_m.size()) : 0, X_WR, options_.segmentation);
  for (const MapSegment& s : features.segments) map_.AddSegment(s);
  for (const MapCluster& c : features.clusters) map_.AddCluster(c);

  // The largest frame's pseudo sides: how far the scan saw nothing.
  const AngleHistogram angles = MakeAngleHistogram(points, options_.histograms);
  const LargestFrame frame = FindLargestFrame(
      MakeDistanceHistograms(points, angles.MainDirectionRad(), options_.histograms),
      options_.frame);
  const double c = std::cos(X_WR.theta_rad), s = std::sin(X_WR.theta_rad);
  const auto to_map = [&](const Eigen::Vector2d& p) {
    return Eigen::Vector2d(X_WR.x_m + c * p.x() - s * p.y(), X_WR.y_m + s * p.x() + c * p.y());
  };
  for (int side = 0; side < 4; ++side) {
    if (!frame.pseudo[side]) continue;
    const auto corners = frame.SideCorners(side);
    MapSegment pseudo;
    pseudo.pseudo = true;
    // Directed with the robot on the left, like the real segments.
    pseudo.line.start = to_map(corners[0]);
    pseudo.line.end = to_map(corners[1]);
    const Eigen::Vector2d d = (pseudo.line.end - pseudo.line.start).normalized();
    const Eigen::Vector2d n(d.y(), -d.x());
    CanonicalNormalForm(std::atan2(n.y(), n.x()), n.dot(pseudo.line.start), &pseudo.line.alpha_rad,
                        &pseudo.line.r_m);
    pseudo.line.num_points = 1;
    map_.AddSegment(pseudo);
  }
  return X_WR;
}

}  // namespace plywood::perception
