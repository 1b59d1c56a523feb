#pragma once

#include <vector>

#include "perception/lines/circle_feature.h"
#include "perception/lines/line_extractor.h"
#include "perception/lines/scan_points.h"

namespace plywood::perception {

// Thin round things (legs, columns of r < 0.1 m) 3-4 m away show 4-6 returns: too few for a line
// (min_points 5 after a mixed pixel goes) and for the round-object stage, which needs 5 points to
// leave a circle 2 degrees of freedom. In a scan whose noise is low (the per-beam median of a
// spot's scans, chords_of_known_round_objects.h) such a group's middle bulges towards the sensor
// by several sigmas (a r = 5 cm leg at 3.5 m: 4 returns over 9 cm, sagitta 2.8 cm), a small box
// face by noise alone. Returns, for each breakpoint group of min_points..max_points returns whose
// circle has a radius <= max_radius_m, is seen from outside, fits every point within
// max_residual_sigmas and whose points bulge beyond the chord between the group's ends by >=
// min_bulge_sigmas, that circle (noise sigma: breakpoints.sigma_m).
struct SmallRoundGroupOptions {
  int min_points = 4;
  int max_points = 6;
  double max_radius_m = 0.15;
  double max_residual_sigmas = 3.0;
  double min_bulge_sigmas = 3.0;
};

std::vector<CircleFeature> SmallRoundGroups(const ScanPoints& scan,
                                            const BreakpointOptions& breakpoints,
                                            const SmallRoundGroupOptions& options = {});

}  // namespace plywood::perception
