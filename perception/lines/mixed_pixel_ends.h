#pragma once

#include <span>
#include <vector>

#include "perception/lines/line_extractor.h"
#include "perception/lines/scan_points.h"

namespace plywood::perception {

// Mixed pixels at the ends of a line (Ye & Borenstein, ICRA 2002). Where a beam's footprint
// straddles a depth edge the laser reports a range between the two surfaces. Such a return joins
// the breakpoint group of the nearer surface whenever the jump to it is inside the breakpoint
// distance (its 0.2 m floor lets it in at short range), as the group's end point, and pulls the
// group's line towards the line of sight: a thin leg, its mixed pixel and nothing else make a
// short "wall" along the beam. At each end of `line` that is an end of its breakpoint group
// (`front_is_group_end`, `back_is_group_end`), the end point is dropped when it lies between the
// two surfaces: towards the surface past the break and no farther from the line than that
// surface's first point (past an opening, where nothing returned: away from the sensor), and off
// the line fitted to the rest of `line` by
// - more than three standard deviations of that offset, breakpoints.sigma_m *
//   sqrt(1 + 1/m + t^2 / S) for m remaining points whose positions along their line spread S
//   about their mean, t the end point's position (the prediction interval of a least-squares
//   line); or
// - more than 3 sigma alone when the rest's line is too ill-determined for that (few points, the
//   end far out), if the end point's range also differs from its inner neighbour's by more than a
//   surface seen at incidence lambda_deg or better moves between the two beams (Borges & Aldon's
//   breakpoint distance r sin(dphi) / sin(lambda - dphi) + 3 sigma, without the min_m floor). A
//   face seen at grazing incidence keeps its end point: it lies on the line of the rest.
// One point per end (the one beam that straddles the edge); a line of two points is left alone.
// `line` holds point indices into scan.points in scan order; for a closed scan the neighbour of
// the last point is the first.
void TrimMixedPixelEnds(const ScanPoints& scan, const BreakpointOptions& breakpoints,
                        bool front_is_group_end, bool back_is_group_end, std::vector<int>* line);

// The same trim at the two ends of one breakpoint group (`group`, scan order) cut into `lines`
// (each a list of point indices, in the group's order): the first line's first point and the last
// line's last point, where they are the group's ends. A closed scan's one group without
// breakpoints has no ends. Returns the points dropped (scan indices, at most two). split_and_merge
// runs it on each group's merged lines before their round test, incremental after its round test;
// in the round-object stage RANSAC and Hough share (RoundObjectPoints) it was measured neutral and
// is not used (docs/lines.md, round 10).
std::vector<int> TrimGroupMixedPixelEnds(const ScanPoints& scan,
                                         const BreakpointOptions& breakpoints,
                                         std::span<const int> group,
                                         std::vector<std::vector<int>>* lines);

}  // namespace plywood::perception
