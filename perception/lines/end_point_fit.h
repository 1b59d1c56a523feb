#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

namespace plywood::perception {

// The iterative end-point fit (Duda & Hart 1973) of one breakpoint group (`group`: point indices
// in scan order): split at the point farthest from the chord between the ends while it is farther
// than threshold_m. The split point stays in the data: it goes to the piece whose line fits it
// better. With skip_single_outliers, a farthest point whose neighbours both lie within half the
// threshold of the chord is a single outlier: left out instead of splitting. Likewise a farthest
// point in a run of at most max_outlier_run points, all beyond the threshold on the sensor's side
// (the origin) with two points on each side within half of it, the inner ones inside the chord's
// ends (0 or 1: single outliers only): split_and_merge leaves out runs too few for a line of their
// own, the 2-3 returns of a table leg a few cm in front of a wall, which otherwise end a piece and
// turn its chord by tens of degrees. Returns the pieces (point indices) in scan order. Shared by
// split_and_merge and the round-object stage (single outliers only there).
std::vector<std::vector<int>> SplitByEndPointFit(std::span<const Eigen::Vector2d> p,
                                                 std::span<const int> group, double threshold_m,
                                                 bool skip_single_outliers,
                                                 int max_outlier_run = 0);

}  // namespace plywood::perception
