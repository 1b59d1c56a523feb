#pragma once

#include <vector>

#include "msgs/laser_scan.h"

namespace plywood::sim {

// A planar scan together with its ground truth: which geom each beam's reported point lies on.
// hit_geom_ids[i] is the MuJoCo geom id, or -1 when beam i reports no point on a surface (no
// return, a dropout, a mixed pixel or an outlier). This is what tells a scorer which ground-truth
// wall segments a scan observed.
struct ScanMeasurement {
  msgs::LaserScan scan;
  std::vector<int> hit_geom_ids;
};

}  // namespace plywood::sim
