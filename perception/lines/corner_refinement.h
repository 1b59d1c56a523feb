#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "perception/lines/tls_line_fit.h"

namespace plywood::perception {

// Corner contamination: an extractor that cuts a breakpoint group into lines by a distance gate
// (the end-point fit's split threshold, incremental's tracking distance) leaves points of one wall
// next to a corner on its neighbour while they lie within the gate of it: a short face then takes
// 2-4 points past the corner and turns by degrees. For the lines of one breakpoint group in scan
// order (`lines`, point indices into `points`; `group` the group's point indices in scan order),
// moves boundary points between each pair of neighbouring lines (no more than one point of the
// group between them, e.g. a skipped outlier; or a split point both share) while a point fits the
// other line better than its own refitted without it. Noise-free corners come out exact.
// `closed_loop`: the group is a whole closed scan, so its last line meets its first.
// `moments`, when given, holds each line's LineMoments with its points added in order (what the
// refinement would otherwise sum first; split_and_merge's merge step has them) and is updated.
void RefineCorners(std::span<const Eigen::Vector2d> points, std::span<const int> group,
                   bool closed_loop, std::vector<std::vector<int>>* lines,
                   std::vector<LineMoments>* moments = nullptr);

}  // namespace plywood::perception
