#include "perception/geometric_map/geometric_mapper.h"

#include <cmath>
#include <numbers>

#include "perception/geometric_map/option_checks.h"

namespace plywood::perception {
namespace {

// alpha and r of the line through line->start and line->end.
void SetNormalForm(LineSegment* line) {
  const Eigen::Vector2d d = (line->end - line->start).normalized();
  CanonicalNormalForm(std::atan2(-d.x(), d.y()), Eigen::Vector2d(d.y(), -d.x()).dot(line->start),
                      &line->alpha_rad, &line->r_m);
}

}  // namespace

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
      map_(options.aggregation, options.segmentation.round_objects) {}

msgs::Pose2D GeometricMapper::AddScan(const msgs::LaserScan& ir, const msgs::RangeRing* sonar,
                                      const msgs::Pose2D& X_OR) {
  // Before anything is counted: a NaN pose would put NaN segments into the map for good.
  RequireFinitePose("X_OR", X_OR);
  const std::vector<RangePoint> points = FuseRanges(ir, sonar, options_.fusion);
  points_seen_ += static_cast<long>(points.size());
  for (const RangePoint& p : points) sonar_points_ += p.from_sonar;
  const bool full_turn =
      std::abs(std::abs(ir.angle_increment_rad) * static_cast<double>(ir.ranges_m.size()) -
               2.0 * std::numbers::pi) < 1e-6;
  // Lines first in the robot frame: the corrector refines the heading on them.
  const ScanFeatures features_R = ExtractScanFeatures(
      points, full_turn ? static_cast<int>(ir.ranges_m.size()) : 0, {}, options_.segmentation);
  std::vector<LineSegment> lines_R;
  for (const MapSegment& s : features_R.segments) lines_R.push_back(s.line);
  const msgs::Pose2D X_WR = corrector_.Correct(X_OR, points, lines_R);
  const double c = std::cos(X_WR.theta_rad), s = std::sin(X_WR.theta_rad);
  const auto to_map = [&](const Eigen::Vector2d& p) {
    return Eigen::Vector2d(X_WR.x_m + c * p.x() - s * p.y(), X_WR.y_m + s * p.x() + c * p.y());
  };
  for (MapSegment segment : features_R.segments) {
    segment.line.start = to_map(segment.line.start);
    segment.line.end = to_map(segment.line.end);
    SetNormalForm(&segment.line);
    map_.AddSegment(segment);
  }
  for (const MapCluster& cluster_R : features_R.clusters) {
    MapCluster cluster = cluster_R;
    cluster.box.setEmpty();
    for (auto corner : {Eigen::AlignedBox2d::BottomLeft, Eigen::AlignedBox2d::BottomRight,
                        Eigen::AlignedBox2d::TopLeft, Eigen::AlignedBox2d::TopRight}) {
      cluster.box.extend(to_map(cluster_R.box.corner(corner)));
    }
    map_.AddCluster(cluster);
  }

  // The largest frame's pseudo sides: how far the scan saw nothing.
  const AngleHistogram angles = MakeAngleHistogram(points, options_.histograms);
  const LargestFrame frame = FindLargestFrame(
      MakeDistanceHistograms(points, angles.MainDirectionRad(), options_.histograms),
      options_.frame);
  // The area inside the new frame has been seen: older pseudo sides there are gone.
  std::vector<Eigen::Vector2d> frame_W;
  for (int side = 0; side < 4; ++side) frame_W.push_back(to_map(frame.SideCorners(side)[0]));
  map_.RemovePseudoInside(frame_W);
  for (int side = 0; side < 4; ++side) {
    if (!frame.pseudo[side]) continue;
    const auto corners = frame.SideCorners(side);
    MapSegment pseudo;
    pseudo.pseudo = true;
    // Directed with the robot on the left, like the real segments.
    pseudo.line.start = to_map(corners[0]);
    pseudo.line.end = to_map(corners[1]);
    SetNormalForm(&pseudo.line);
    pseudo.line.num_points = 1;
    map_.AddSegment(pseudo);
  }
  return X_WR;
}

}  // namespace plywood::perception
