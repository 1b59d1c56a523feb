#pragma once

#include <span>
#include <vector>

#include "msgs/pose2d.h"
#include "perception/geometric_map/map_features.h"
#include "perception/geometric_map/range_fusion.h"
#include "perception/lines/split_and_merge_extractor.h"
#include "perception/lines/tls_line_fit.h"

namespace plywood::perception {

// Seed 003's segmentation and fit of one scan:
// 1. break the scan (in beam order, the turn closed at its widest gap) where consecutive points
//    are farther apart than dist_max_m; groups of fewer than min_line_points become clusters
//    (groups of fewer than min_cluster_points, a lone outlier, are dropped);
// 2. split each group by iterative end-point fit where the farthest point is more than r_min_m
//    from the chord;
// 3. fit each piece of at least min_line_points in normal form (the modal filter by default, or
//    total least squares); its inliers are the points within inlier_distance_m of the line; a
//    piece with fewer than min_inlier_fraction inliers has low confidence and is not a line; the
//    modal filter's inliers are refitted by total least squares (its own direction, a truncated
//    mean of noisy pair directions, leans towards its bin grid by tenths of a degree);
// 4. round small objects are not lines (round_objects, piece_curvature.h): the pieces of a group
//    that one small circle seen from outside explains (a column seen whole: the line extractors'
//    test, round_object_filter.h), and a piece whose inliers bend towards the observer
//    significantly, with a small implied radius (a chord of a column); their points become
//    clusters. The observer is X_WR's position (the Magellan's scanner is at its centre);
// 5. endpoints: where two fitted pieces of one group meet, the intersection of their lines (when it
//    lies within max_intersection_shift_m of the shared point, else the projections); elsewhere
//    the projection of the first / last point;
// 6. a group that gave no line (a column, a table leg, clutter) becomes a cluster when its points
//    fit in a box of max_cluster_size_m (larger ones are clutter and dropped).
// Defaults are assumptions: 0.15 m breaks at doorways, posts and behind obstacles while 1.8 deg
// steps at 3 m are 9.4 cm; r_min 3 cm is 6 IR noise sigmas.
struct SegmentationOptions {
  double dist_max_m = 0.15;
  int min_line_points = 8;
  int min_cluster_points = 3;
  double max_cluster_size_m = 0.8;
  double r_min_m = 0.03;
  LineFitMethod fit = LineFitMethod::kModal;
  ModalFitOptions modal;
  double inlier_distance_m = 0.02;
  double min_inlier_fraction = 0.7;
  double max_intersection_shift_m = 0.15;
  RoundPieceOptions round_objects;

  // @throws std::invalid_argument starting with the field's name.
  void Validate() const;
};

struct ScanFeatures {
  std::vector<MapSegment> segments;  // real, in the map frame
  std::vector<MapCluster> clusters;  // in the map frame
};

// The lines and clusters of one scan's points (robot frame, beam order, from FuseRanges) seen from
// pose X_WR, in the map frame W. `beam_count` is the scan's number of beams (to close a full
// turn; 0: the scan is not a full turn).
ScanFeatures ExtractScanFeatures(std::span<const RangePoint> points_R, int beam_count,
                                 const msgs::Pose2D& X_WR, const SegmentationOptions& options);

// The fit of points[indices] by `options.fit`, with its inliers (the confidence record; their
// indices in `inliers` when not null).
MapSegment FitMapSegment(std::span<const Eigen::Vector2d> points, std::span<const int> indices,
                         const SegmentationOptions& options, std::vector<int>* inliers = nullptr);

}  // namespace plywood::perception
