#pragma once

#include <vector>

#include "perception/lines/circle_feature.h"
#include "perception/lines/scan_points.h"
#include "perception/lines/split_and_merge_extractor.h"

namespace plywood::perception {

// The round objects a lower-noise scan of a spot shows (the per-beam median of the spot's scans;
// `options.breakpoints.sigma_m` is its noise), for chords_of_known_round_objects.h: those
// split_and_merge's round-object stage finds and the small round groups of 4-6 returns too few
// for that stage (small_round_groups.h), each kept only when SeenAsARoundObject.
std::vector<CircleFeature> RoundObjectsOfQuietScan(const ScanPoints& quiet_scan,
                                                   const SplitAndMergeOptions& options);

// Whether `circle` (fitted to quiet_scan's points, noise sigma_m) is a round object the scan
// shows, not a small box face the fit bent round: (a) the circle explains its points to their
// noise (residual sum of squares within the chi-square quantile of n - 3 degrees of freedom at
// 1 %: a face with one grazing return of its neighbouring face 15 cm behind its end fits a small
// circle with 16 sigma^2 over 6 points), and (b) its points lie around the line of sight to its
// centre, where a round object's nearest point is, with at least a quarter of their angular span
// on each side of it, unless the return past the short side is nearer (something hides that side:
// an edge chord of a partly hidden column). A face seen at an angle bends a circle whose centre
// lies off to one side.
bool SeenAsARoundObject(const ScanPoints& quiet_scan, const CircleFeature& circle, double sigma_m);

}  // namespace plywood::perception
