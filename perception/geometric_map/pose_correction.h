#pragma once

#include <deque>
#include <span>
#include <vector>

#include "msgs/pose2d.h"
#include "perception/geometric_map/range_fusion.h"
#include "perception/geometric_map/scan_histograms.h"
#include "perception/lines/line_segment.h"

namespace plywood::perception {

// Seed 003 says the histograms "are meant to correct pose errors" and leaves the algorithm open.
// This one correlates, as the paper suggests:
//  - heading: the scan's angle histogram, voted in the map frame at the predicted heading, is
//    cross-correlated with the map's angle histogram (the sum over all corrected scans, which does
//    not depend on where the robot is); the best shift within +-(max_heading_step_deg + the
//    odometry's turn since the last scan, at most 45 deg) corrects the heading, then the
//    points-weighted mean direction of the scan's fitted lines within
//    refine_window_deg of the map's main direction or square to it refines it below the bin size
//    (the virtual lines are too short for that: 5 mm noise tilts a 14 cm one by 3 deg);
//  - position: in the map's main frame (the first scan's alpha_max), the scan's X and Y distance
//    histograms are cross-correlated with those of the last reference_scans corrected scans within
//    reach; the best shift within +-max_shift_m corrects x and y (bins of position_bin_m), refined
//    below the bin (refine_position) by the mean signed distance from the scan's voting points to
//    the reference's within a bin of them, as the heading is refined on the fitted lines. With
//    refine_position or require_peak_support the axis is left alone when fewer than
//    min_peak_votes scan points have a reference point within a bin at the correlation's shift
//    (docs/geometric_map.md, "Stop 54", "Stop 55"). As in the
//    paper's distance histograms, a point votes on an axis only when its virtual line is within
//    histograms.max_wall_tilt_deg of square to it: the points of a wall along the axis, denser
//    behind the robot where earlier scans saw it, would otherwise pull every shift back along the
//    path. An axis whose scan histogram has no three neighbouring bins with min_peak_votes points
//    (no wall across it, e.g. along a corridor) is left alone. With require_reference_support a
//    scan point votes only where the reference holds min_peak_votes points within max_shift_m of
//    it, and the axis is left alone unless min_peak_votes points vote: a wall seen for the first
//    time, with at most a glimpse of it in the reference, does not move the position
//    (docs/geometric_map.md, "Stop 53").
// The correction is kept as a transform X_WO from the odometry frame to the map frame, so the
// odometry keeps integrating undisturbed. The heading is anchored to the whole map, so its error
// stays bounded by the histogram resolution; the position is anchored to recent scans only, so
// it can still drift, more slowly than odometry. Scans with fewer than min_virtual_lines votes are
// not corrected (and not used as reference).
struct PoseCorrectionOptions {
  bool heading = true;
  // Helps over the office and the generated rooms (docs/geometric_map.md, "Pose correction").
  bool position = true;
  double max_heading_step_deg = 3.0;
  double refine_window_deg = 2.0;
  double max_shift_m = 0.1;
  double position_bin_m = 0.02;
  int min_virtual_lines = 30;
  int min_peak_votes = 10;
  int reference_scans = 10;
  // Scan points vote on the position only where the reference has a wall to match them with. Off:
  // it mends office seed 1 (IR only) but costs more often than it helps (docs/geometric_map.md,
  // "Stop 53").
  bool require_reference_support = false;
  // The position shift refined below position_bin_m (the scan's wall points against the
  // reference's within a bin of them), as the heading is on the fitted lines; a shift matched by
  // fewer than min_peak_votes scan points leaves the axis alone. Off: it lowers the mean position
  // error in the office and every generated family, but loses a segment's precision in a few
  // generated runs and raises the office's final position error (docs/geometric_map.md, "Stop 53",
  // "Stop 54").
  bool refine_position = false;
  // The correlation's shift kept only where min_peak_votes scan points have a reference point
  // within position_bin_m at it (refine_position always applies this rule): a peak of one pair, a
  // wall seen first against an unrelated reference point, is not a match. On since stop 55 (a
  // fix): it mends every such jump traced and changes no shipped output; it costs two segments in
  // one generated family of one seed, where the later drift happened to be smaller with the wrong
  // jump (docs/geometric_map.md, "Stop 55").
  bool require_peak_support = true;

  // @throws std::invalid_argument starting with the field's name.
  void Validate() const;
};

class HistogramPoseCorrector {
 public:
  HistogramPoseCorrector(const HistogramOptions& histograms, const PoseCorrectionOptions& options);

  // The corrected map-frame pose of a scan taken at odometry pose X_OR; `points_R` in the robot
  // frame, beam order, `lines_R` the lines fitted to them (robot frame). Updates the correction
  // and the reference histograms. A non-finite X_OR throws std::invalid_argument "X_OR: ...".
  msgs::Pose2D Correct(const msgs::Pose2D& X_OR, std::span<const RangePoint> points_R,
                       std::span<const LineSegment> lines_R = {});

  // The current odometry-to-map correction.
  const msgs::Pose2D& X_WO() const { return X_WO_; }

 private:
  double HeadingCorrection(std::span<const RangePoint> points_R,
                           std::span<const LineSegment> lines_R, double heading_rad,
                           double window_rad) const;
  // A point of a wall across axis 0 (the map's main direction) or axis 1 (square to it).
  struct AxisPoint {
    Eigen::Vector2d p_W;
    int axis = 0;
  };
  // Shift (m) that best aligns `scan` coordinates along `axis` (number axis_index) with the
  // reference's.
  bool AxisShift(const std::vector<double>& scan, int axis_index, const Eigen::Vector2d& axis,
                 const Eigen::Vector2d& robot_W, double* shift_m) const;

  HistogramOptions histogram_options_;
  PoseCorrectionOptions options_;
  msgs::Pose2D X_WO_;
  std::vector<double> map_angle_votes_;
  bool has_reference_ = false;
  double map_alpha_rad_ = 0.0;
  double last_odometry_theta_rad_ = 0.0;  // of the last scan that joined the reference
  std::deque<std::vector<AxisPoint>> recent_points_W_;
};

}  // namespace plywood::perception
