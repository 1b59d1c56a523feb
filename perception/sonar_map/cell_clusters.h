#pragma once

#include <Eigen/Core>
#include <vector>

namespace plywood::perception {

// The cells as groups: two cells are in one group when a chain of its cells leads from one to the
// other, each step leaving at most `max_gap` cells between them along x and along y (0: the
// 8-connected components). Every cell is in exactly one group; groups come in the order of their
// first cell in `cells`, their cells in input order. Empty input gives no group.
std::vector<std::vector<Eigen::Vector2i>> ClustersWithinGap(
    const std::vector<Eigen::Vector2i>& cells, int max_gap);

}  // namespace plywood::perception
