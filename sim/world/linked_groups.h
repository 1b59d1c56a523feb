#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

namespace plywood::sim {

// The groups a symmetric relation makes among items 0..n-1, taken transitively (union-find): each
// item's group is named by the smallest index in it, so groups come out in the order of their
// first items. `linked(i, j)` is asked once for each pair i < j (faces continuing one another,
// faces a map scorer joins across gaps).
template <typename Linked>
std::vector<int> LinkedGroups(int n, Linked linked) {
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (linked(i, j)) {
        const int ri = root(i), rj = root(j);
        parent[std::max(ri, rj)] = std::min(ri, rj);
      }
    }
  }
  for (int k = 0; k < n; ++k) parent[k] = root(k);
  return parent;
}

}  // namespace plywood::sim
