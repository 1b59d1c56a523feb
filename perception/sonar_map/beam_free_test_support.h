#pragma once

#include <Eigen/Core>

#include "msgs/pose2d.h"
#include "msgs/range_ring.h"
#include "perception/sonar_map/beam_free_grid.h"
#include "perception/sonar_map/log_odds_grid.h"

// Hand-made axis echoes for the tests of the rules that read them (faces heard apart, well-painted
// groups).
namespace plywood::perception {

// 10 cm cells from the origin, 2 x 2 m: cell (ix, iy) spans [0.1 ix, 0.1 (ix + 1)] along x.
inline BeamFreeGrid EmptyBeams() {
  LogOddsGridOptions geometry;
  geometry.resolution_m = 0.1;
  geometry.origin_xy = {0.0, 0.0};
  geometry.width = 20;
  geometry.height = 20;
  return BeamFreeGrid(geometry, {});
}

// `times` readings of one transducer at `from` pointing along `heading`, echoing at `range`.
inline void Hear(BeamFreeGrid& beams, const Eigen::Vector2d& from, double heading, double range,
                 int times = 2) {
  msgs::RangeRing ring;
  ring.readings.push_back({msgs::Pose2D{0.0, 0.0, 0.0}, range, true});
  for (int k = 0; k < times; ++k) beams.Integrate(ring, {from.x(), from.y(), heading});
}

}  // namespace plywood::perception
