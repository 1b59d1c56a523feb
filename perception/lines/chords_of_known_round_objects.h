#pragma once

#include <span>
#include <vector>

#include "perception/lines/circle_feature.h"
#include "perception/lines/line_segment.h"
#include "perception/lines/scan_points.h"

namespace plywood::perception {

// One scan cannot tell a 4-7 point chord of a thin column from a short box face: the chord's
// bulge is within 1-2 noise sigmas (docs/lines.md, issue 13). A rig that takes several scans from
// one spot sees the same round objects in every one of them, and the per-beam median of those
// scans has ~3x less noise, enough to find the column there (round_objects_of_quiet_scan.h). This
// removes from one scan's `lines` each line that is a chord of such a known round object: at
// least min_on_rim_fraction of its points (the scan points in its index range, or without scan
// order the points within rim_sigmas noise sigmas of the segment) lie within rim_sigmas x
// `noise_sigma_m` (one scan's noise) of one circle's rim, and the line is no longer than the
// circle's diameter plus that tolerance. A box face is never on a circle's rim unless the other
// view called it round. Lines with fewer than 2 points found are kept.
struct KnownRoundObjectOptions {
  double rim_sigmas = 3.0;
  double min_on_rim_fraction = 0.8;
};

// Returns how many lines were removed. A circle whose centre is not finite or whose radius is not
// a finite number > 0, noise_sigma_m or rim_sigmas not a finite number > 0, or
// min_on_rim_fraction outside (0, 1] throws std::invalid_argument naming it; lines untouched.
int RemoveChordsOfKnownRoundObjects(const ScanPoints& scan,
                                    std::span<const CircleFeature> known_round_objects,
                                    double noise_sigma_m, const KnownRoundObjectOptions& options,
                                    std::vector<LineSegment>* lines);

}  // namespace plywood::perception
