#pragma once

#include <vector>

#include "perception/lines/line_extractor.h"
#include "perception/lines/round_object_filter.h"
#include "perception/lines/scan_points.h"

namespace plywood::perception {

// A round object just beyond a range cut shows only its near side inside the cut: a 4-6 point
// cap of a 0.2 m column 3.95 m away under a 4 m cut is 0.1-0.15 m wide with a sagitta of ~1 cm,
// flat within the noise, with missing beams on both sides -- a wall seen at the cut looks the
// same. The returns the cut removed (ScanPoints::beyond_cut_*) tell them apart: a wall continues
// past the cut along its line, a column's flanks curve away and end at a jump to what lies
// behind. A breakpoint group whose end meets beams that returned beyond the cut is extended by
// those returns (as far as the breakpoint rule keeps them in one group), the extension is cut by
// the end-point fit and tested by RemoveRoundObjects as a group of its own, and every line of
// `lines` whose points all lie on a round run found there is dropped: the same round test as
// inside the cut, on the whole object. The returns past the cut never give a line; scans without
// a cut (no beyond_cut_* returns) are left as they are.
// `group` holds the group's point indices in scan order, `lines` its lines (point indices).
void RemoveRoundObjectsPastRangeCut(const ScanPoints& scan, const BreakpointOptions& breakpoints,
                                    double split_threshold_m, const RoundObjectOptions& options,
                                    const std::vector<int>& group,
                                    std::vector<std::vector<int>>* lines);

}  // namespace plywood::perception
