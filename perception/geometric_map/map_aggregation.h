#pragma once

#include <vector>

#include "perception/geometric_map/map_features.h"

namespace plywood::perception {

// Seed 003's global map aggregation. A new segment's candidates are the map's segments whose
// bounding rectangles, each grown by inflate_m, intersect its own; a candidate is accepted when
// the directions differ by at most max_angle_diff_deg, every endpoint of each lies within
// max_endpoint_distance_m of the other's line, and the two stretches overlap or leave a gap of at
// most max_gap_m along the line. Segments are directed with their observer on the left (scan
// order), so the two faces of a partition, seen from its two sides, never merge. The merged line
// has the points-weighted mean direction, passes through the points-weighted mean of the
// midpoints and spans the outermost endpoints. 'real' wins over 'pseudo': a pseudo side later
// seen for real becomes the real segment (its extent only bounded what had been seen). A merged
// segment is tried again against the rest until nothing merges. Clusters merge when their boxes,
// grown by cluster_inflate_m, intersect and their union stays within max_cluster_size_m. A real
// segment counts as confirmed once segments of at least min_observations scans merged into it: a
// sonar echo placed square to a transducer that heard it off-axis gives a line each scan at a
// different offset, which never merges, while a true surface is seen again and again; and when the
// curvature its scans' pieces show together (inverse-variance mean) does not make it a small round
// object (round_objects: a column's chords too faint to tell in one scan, merged from nearby
// poses). A side of a new largest frame removes the pseudo segments lying inside that frame or on
// its sides within 2 cm (the area was seen since). Defaults are assumptions: 5 deg and 6 cm accept
// one wall seen from two poses with a few centimetres of pose error and refuse parallel walls a
// door frame apart; the gap stays well below a 0.9 m door, so a wall is not bridged across a
// doorway.
struct AggregationOptions {
  double inflate_m = 0.1;
  double max_angle_diff_deg = 5.0;
  double max_endpoint_distance_m = 0.06;
  double max_gap_m = 0.3;
  double cluster_inflate_m = 0.05;
  double max_cluster_size_m = 0.8;  // clusters do not grow beyond this (a chain along a wall)
  int min_observations = 3;

  // @throws std::invalid_argument starting with the field's name.
  void Validate() const;
};

class GeometricMap {
 public:
  explicit GeometricMap(const AggregationOptions& options = {},
                        const RoundPieceOptions& round_objects = {});

  void AddSegment(const MapSegment& segment);
  void AddCluster(const MapCluster& cluster);

  // Drops the pseudo segments with both ends inside the convex polygon `corners_W` (in order).
  void RemovePseudoInside(const std::vector<Eigen::Vector2d>& corners_W);

  // Every segment: real (confirmed or not) and pseudo.
  const std::vector<MapSegment>& segments() const { return segments_; }
  bool Confirmed(const MapSegment& s) const {
    return !s.pseudo && s.observations >= options_.min_observations &&
           !round_objects_.IsRound(s.curvature);
  }
  const std::vector<MapCluster>& clusters() const { return clusters_; }
  // Whether `a` and `b` pass the acceptance test (for tests and diagnostics).
  bool Mergeable(const MapSegment& a, const MapSegment& b) const;

 private:
  MapSegment Merge(const MapSegment& a, const MapSegment& b) const;

  AggregationOptions options_;
  RoundPieceOptions round_objects_;
  std::vector<MapSegment> segments_;
  std::vector<MapCluster> clusters_;
};

}  // namespace plywood::perception
