#pragma once

#include <Eigen/Geometry>

#include "perception/geometric_map/piece_curvature.h"
#include "perception/lines/line_segment.h"

namespace plywood::perception {

// A line of the geometric map (seed 003's segment record): the line in normal form with its
// endpoints and direction (`line`, in the map frame), the tag 'real' (seen) or 'pseudo' (a side of
// a largest frame where the scan saw nothing up to d_max), and its confidence: the number of points
// behind it (line.num_points) and how many of them the fit kept as inliers.
struct MapSegment {
  LineSegment line;
  bool pseudo = false;
  int inliers = 0;
  int observations = 1;  // scans whose segments merged into this one
  // How the points bend (a round object's chords do), combined over the merged scans.
  PieceCurvature curvature;

  double InlierFraction() const {
    return line.num_points > 0 ? static_cast<double>(inliers) / line.num_points : 0.0;
  }
};

// A small object the map keeps as a rectangle (seed 003's 'cluster'): the axis-aligned box of its
// points in the map frame.
struct MapCluster {
  Eigen::AlignedBox2d box;
  int points = 0;
};

}  // namespace plywood::perception
