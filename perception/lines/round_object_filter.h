#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "perception/lines/circle_feature.h"
#include "perception/lines/line_extractor.h"
#include "perception/lines/scan_points.h"

namespace plywood::perception {

// Round objects (columns, table legs, bins) have no line to give, yet an ordered extractor cuts
// them into chords that match no wall: most of the false lines in simulated rooms with columns.
// After the extractor has cut a breakpoint group into lines, runs of two or more consecutive
// lines that one small circle explains are dropped. A run is round when, after dropping points
// more than 3 noise sigmas off the circle (the mixed pixels where a column meets the wall behind
// it), at least 80 % of its points remain, the circle is seen from outside over at least
// min_round_arc_deg (45 deg) of its circumference (a column shows nearly half of it; 1 cm noise
// inflates a thin column's fitted circle so its few samples cover 45-100 deg of it; clutter that
// happens to fit a circle shows a short piece), a run that is not its whole breakpoint group bends
// away from one straight line by >= 25 noise sigma^2 of residual (a bump of noise in a wall does
// not), and the circle (3 parameters) explains the points
//   (a) at least as well as the run's lines (2 parameters each plus the split points), residual
//       variance over degrees of freedom, the lines refitted to the same points; or
//   (b) at the noise level (RMS <= 1.5 sigma) with the lines' gain within what their extra
//       parameters buy from noise (3 sigma^2 each): few points let two chords fit the noise.
// A run that is the whole group (>= 2 lines, both ends breaks: an object seen whole) needs no
// min_round_arc_deg when no point had to be trimmed: noise shrinks a small column's fitted arc.
// (min_round_arc_deg was 100 deg before issue 13's last round; docs/lines.md has both.)
// Noise-free polygons keep their edges (their lines fit exactly, a circle cannot). A single line
// is dropped only when it is its whole breakpoint group (a thin column's one chord), with >= 5
// points and a bulge of >= 1.5 sigma; it costs the real CARMEN logs ~0.01 of explained rays
// (docs/lines.md).
struct RoundObjectOptions {
  bool reject_round_objects = true;
  double max_round_radius_m = 0.5;  // larger curves are walls; cutting them into chords is right
  int min_round_points = 8;         // fewer points cannot tell an arc from two lines
  double min_round_arc_deg = 45.0;
  // JoinRoundObjectsAcrossOccluders (split_and_merge): a column whose middle a nearer object hides
  // is one round object in two breakpoint groups.
  bool join_across_occluders = true;
  // RemoveRoundObjectsPastRangeCut (split_and_merge): a group at a range cut is tested for a
  // round object together with the returns the cut removed next to it.
  bool round_past_range_cut = true;

  // @throws std::invalid_argument starting with the field name.
  void Validate() const;
};

// Removes from `lines` (the lines of one breakpoint group in scan order, each a list of point
// indices into `points`; sensor at the origin) every run of consecutive lines that is a round
// object seen from outside. `noise_sigma_m` is the range noise of one point. Each run removed is
// appended to `circles` (when given) as the circle fitted to its points: a run is round only when
// that circle passes the feature gates (circle_feature.h: radius <= max_round_radius_m, RMS
// residual <= 2 sigma, no point beyond 4 sigma), so every removed run is reported.
void RemoveRoundObjects(std::span<const Eigen::Vector2d> points, double noise_sigma_m,
                        const RoundObjectOptions& options, std::vector<std::vector<int>>* lines,
                        std::vector<CircleFeature>* circles = nullptr);

// A round object partly hidden by a nearer one (a column behind a column or a table leg) shows
// on both sides of the occluder as two breakpoint groups, each an edge chord from its silhouette
// to the occlusion edge: short arcs that one scan cannot tell from box faces. The object continues
// behind the occluder, so the two sides are tested together. `group_lines` holds each breakpoint
// group's lines (point indices in scan order), groups in scan order. For two consecutive groups
// whose facing ends are both occlusion edges -- every return between the last line of the one and
// the first line of the other (at least one, no beam without a return) is nearer than both of
// those lines' facing end points -- the lines of the two groups are tested as one group by
// RemoveRoundObjects, and a round run found there that holds both facing lines (the object across
// its occluder) is dropped from both groups and reported as one circle. Collinear wall pieces
// behind an occluder fit no small circle; a box's two faces around a hidden corner fit their two
// lines better than a circle, as in a group of their own.
void JoinRoundObjectsAcrossOccluders(const ScanPoints& scan, double noise_sigma_m,
                                     const RoundObjectOptions& options,
                                     std::vector<std::vector<std::vector<int>>>* group_lines,
                                     std::vector<CircleFeature>* circles = nullptr);

// The same stage for extractors that look for lines among all of a scan's points (RANSAC, Hough):
// the scan's breakpoint groups, each cut by the end-point fit at split_threshold_m
// (end_point_fit.h), then RemoveRoundObjects on each group's pieces. Returns per point whether it
// lies on a round object (all zero when options.reject_round_objects is false); the circles found
// are appended to `circles` when given.
std::vector<char> RoundObjectPoints(const ScanPoints& scan, const BreakpointOptions& breakpoints,
                                    double split_threshold_m, const RoundObjectOptions& options,
                                    std::vector<CircleFeature>* circles = nullptr);

}  // namespace plywood::perception
