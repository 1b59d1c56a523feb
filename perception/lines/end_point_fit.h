#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

namespace plywood::perception {

// The iterative end-point fit (Duda & Hart 1973) of one breakpoint group (`group`: point indices
// in scan order): split at the point farthest from the chord between the ends while it is farther
// than threshold_m. The split point stays in the data: it goes to the piece whose line fits it
// better. With skip_single_outliers, a farthest point whose neighbours both lie within half the
// threshold of the chord is a single outlier: left out instead of splitting. Returns the pieces
// (point indices) in scan order. Shared by split_and_merge and the round-object stage.
std::vector<std::vector<int>> SplitByEndPointFit(std::span<const Eigen::Vector2d> p,
                                                 std::span<const int> group, double threshold_m,
                                                 bool skip_single_outliers);

}  // namespace plywood::perception
