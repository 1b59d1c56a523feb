#pragma once

#include <vector>

#include "msgs/laser_scan.h"
#include "msgs/pose2d.h"
#include "msgs/range_ring.h"
#include "perception/geometric_map/largest_frame.h"
#include "perception/geometric_map/map_aggregation.h"
#include "perception/geometric_map/pose_correction.h"
#include "perception/geometric_map/range_fusion.h"
#include "perception/geometric_map/scan_histograms.h"
#include "perception/geometric_map/scan_segmentation.h"

namespace plywood::perception {

// Every option of seed 003's pipeline (each struct documents its defaults).
struct GeometricMapOptions {
  FusionOptions fusion;
  HistogramOptions histograms;
  LargestFrameOptions frame;
  PoseCorrectionOptions correction;
  SegmentationOptions segmentation;
  AggregationOptions aggregation;

  // @throws std::invalid_argument starting with the field's name.
  void Validate() const;
};

// Seed 003 (Skrzypczynski & Wozniak 1994) on one robot, scan by scan: fuse the IR scan with the
// sonar ring (range_fusion.h), correct the odometry pose from the scan's histograms
// (pose_correction.h), find the largest frame (largest_frame.h) whose pseudo sides enter the map
// as 'pseudo' segments, segment and fit the scan (scan_segmentation.h), and aggregate its lines and
// clusters into the global map (map_aggregation.h). The map frame is the odometry frame at the
// first scan.
class GeometricMapper {
 public:
  // @throws std::invalid_argument from options.Validate().
  explicit GeometricMapper(const GeometricMapOptions& options);

  // One IR scan with the sonar ring read with it (null: none) at odometry pose X_OR. Returns the
  // corrected pose of the scan in the map frame. A non-finite X_OR throws std::invalid_argument
  // "X_OR: ..." (as do the scan's angles, FuseRanges).
  msgs::Pose2D AddScan(const msgs::LaserScan& ir, const msgs::RangeRing* sonar,
                       const msgs::Pose2D& X_OR);

  const GeometricMap& map() const { return map_; }
  long points_seen() const { return points_seen_; }
  long sonar_points() const { return sonar_points_; }
  const GeometricMapOptions& options() const { return options_; }

 private:
  GeometricMapOptions options_;
  HistogramPoseCorrector corrector_;
  GeometricMap map_;
  long points_seen_ = 0;
  long sonar_points_ = 0;
};

}  // namespace plywood::perception
