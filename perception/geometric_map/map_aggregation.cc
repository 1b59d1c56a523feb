#include "perception/geometric_map/map_aggregation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "msgs/angle_units.h"
#include "msgs/pose2d.h"
#include "perception/geometric_map/option_checks.h"

namespace plywood::perception {
namespace {

double Direction(const MapSegment& s) {
  const Eigen::Vector2d d = s.line.end - s.line.start;
  return std::atan2(d.y(), d.x());
}

Eigen::AlignedBox2d Box(const MapSegment& s, double grow_m) {
  Eigen::AlignedBox2d box(s.line.start.cwiseMin(s.line.end), s.line.start.cwiseMax(s.line.end));
  return Eigen::AlignedBox2d(box.min().array() - grow_m, box.max().array() + grow_m);
}

// Distance of p from the infinite line through a and b.
double LineDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length = ab.norm();
  if (length < 1e-12) return (p - a).norm();
  const Eigen::Vector2d v = p - a;
  return std::abs(ab.x() * v.y() - ab.y() * v.x()) / length;
}

// The segment with direction `theta` through `centre` spanning the projections of `ends`, with
// its normal form.
LineSegment Spanning(double theta, const Eigen::Vector2d& centre,
                     const std::vector<Eigen::Vector2d>& ends) {
  const Eigen::Vector2d d(std::cos(theta), std::sin(theta));
  double lo = 0.0, hi = 0.0;
  for (std::size_t k = 0; k < ends.size(); ++k) {
    const double t = (ends[k] - centre).dot(d);
    lo = k ? std::min(lo, t) : t;
    hi = k ? std::max(hi, t) : t;
  }
  LineSegment line;
  line.start = centre + lo * d;
  line.end = centre + hi * d;
  const Eigen::Vector2d n(d.y(), -d.x());
  CanonicalNormalForm(std::atan2(n.y(), n.x()), n.dot(centre), &line.alpha_rad, &line.r_m);
  return line;
}

}  // namespace

void AggregationOptions::Validate() const {
  RequireOption(inflate_m >= 0.0 && inflate_m <= 5.0, "inflate_m", "must be in [0, 5]", inflate_m);
  RequireOption(max_angle_diff_deg > 0.0 && max_angle_diff_deg <= 45.0, "max_angle_diff_deg",
                "must be in (0, 45]", max_angle_diff_deg);
  RequireOption(max_endpoint_distance_m > 0.0 && max_endpoint_distance_m <= 2.0,
                "max_endpoint_distance_m", "must be in (0, 2]", max_endpoint_distance_m);
  RequireOption(max_gap_m >= 0.0 && max_gap_m <= 5.0, "max_gap_m", "must be in [0, 5]", max_gap_m);
  RequireOption(max_cluster_size_m > 0.0 && max_cluster_size_m <= 10.0, "max_cluster_size_m",
                "must be in (0, 10]", max_cluster_size_m);
  RequireOption(min_observations >= 1 && min_observations <= 1000, "min_observations",
                "must be in [1, 1000]", min_observations);
  RequireOption(cluster_inflate_m >= 0.0 && cluster_inflate_m <= 5.0, "cluster_inflate_m",
                "must be in [0, 5]", cluster_inflate_m);
}

GeometricMap::GeometricMap(const AggregationOptions& options,
                           const RoundPieceOptions& round_objects)
    : options_(options), round_objects_(round_objects) {}

bool GeometricMap::Mergeable(const MapSegment& a, const MapSegment& b) const {
  if (!Box(a, options_.inflate_m).intersects(Box(b, options_.inflate_m))) return false;
  const double d_angle = std::abs(msgs::WrapAngle(Direction(a) - Direction(b)));
  if (d_angle > options_.max_angle_diff_deg * kDegToRad) return false;
  for (const auto& [p, q] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
    for (const Eigen::Vector2d& end : {p->line.start, p->line.end}) {
      if (LineDistance(end, q->line.start, q->line.end) > options_.max_endpoint_distance_m) {
        return false;
      }
    }
  }
  // Gap between the two stretches along a's direction.
  const Eigen::Vector2d d = (a.line.end - a.line.start).normalized();
  const double a0 = 0.0, a1 = (a.line.end - a.line.start).norm();
  const double b0 = (b.line.start - a.line.start).dot(d), b1 = (b.line.end - a.line.start).dot(d);
  const double gap = std::max(std::min(b0, b1) - a1, a0 - std::max(b0, b1));
  return gap <= options_.max_gap_m;
}

MapSegment GeometricMap::Merge(const MapSegment& a, const MapSegment& b) const {
  if (a.pseudo != b.pseudo) {
    MapSegment real = a.pseudo ? b : a;
    real.observations = a.observations + b.observations;
    return real;
  }
  const double wa = std::max(1, a.line.num_points), wb = std::max(1, b.line.num_points);
  const double ta = Direction(a), tb = ta + msgs::WrapAngle(Direction(b) - ta);
  const double theta = (wa * ta + wb * tb) / (wa + wb);
  const Eigen::Vector2d centre =
      (wa * 0.5 * (a.line.start + a.line.end) + wb * 0.5 * (b.line.start + b.line.end)) / (wa + wb);
  MapSegment merged;
  merged.line = Spanning(theta, centre, {a.line.start, a.line.end, b.line.start, b.line.end});
  merged.line.num_points = a.line.num_points + b.line.num_points;
  merged.inliers = a.inliers + b.inliers;
  merged.observations = a.observations + b.observations;
  merged.curvature = a.curvature.Combined(b.curvature);
  merged.pseudo = a.pseudo;
  return merged;
}

void GeometricMap::AddSegment(const MapSegment& segment) {
  MapSegment current = segment;
  for (;;) {
    std::size_t k = 0;
    while (k < segments_.size() && !Mergeable(segments_[k], current)) ++k;
    if (k == segments_.size()) break;
    current = Merge(segments_[k], current);
    segments_.erase(segments_.begin() + static_cast<long>(k));
  }
  segments_.push_back(current);
}

void GeometricMap::RemovePseudoInside(const std::vector<Eigen::Vector2d>& corners_W) {
  const auto inside = [&](const Eigen::Vector2d& p) {
    for (std::size_t k = 0; k < corners_W.size(); ++k) {
      const Eigen::Vector2d a = corners_W[k], b = corners_W[(k + 1) % corners_W.size()];
      const Eigen::Vector2d ab = b - a, ap = p - a;
      // Sides of successive frames often coincide (the same wall bounds both): on a side counts.
      if (ab.x() * ap.y() - ab.y() * ap.x() < -0.02 * ab.norm()) return false;
    }
    return true;
  };
  std::erase_if(segments_, [&](const MapSegment& s) {
    return s.pseudo && inside(s.line.start) && inside(s.line.end);
  });
}

void GeometricMap::AddCluster(const MapCluster& cluster) {
  MapCluster current = cluster;
  const auto grown = [&](const Eigen::AlignedBox2d& b) {
    return Eigen::AlignedBox2d(b.min().array() - options_.cluster_inflate_m,
                               b.max().array() + options_.cluster_inflate_m);
  };
  for (;;) {
    std::size_t k = 0;
    const auto merges = [&](const MapCluster& other) {
      return grown(other.box).intersects(grown(current.box)) &&
             other.box.merged(current.box).sizes().maxCoeff() <= options_.max_cluster_size_m;
    };
    while (k < clusters_.size() && !merges(clusters_[k])) ++k;
    if (k == clusters_.size()) break;
    current.box.extend(clusters_[k].box);
    current.points += clusters_[k].points;
    clusters_.erase(clusters_.begin() + static_cast<long>(k));
  }
  clusters_.push_back(current);
}

}  // namespace plywood::perception
