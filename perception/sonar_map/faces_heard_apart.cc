#include "perception/sonar_map/faces_heard_apart.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

#include "perception/sonar_map/cell_clusters.h"

namespace plywood::perception {

int EchoesFacing(const std::vector<Eigen::Vector2i>& faces,
                 const std::vector<Eigen::Vector2i>& other, const BeamFreeGrid& beam_free) {
  if (other.empty()) return 0;
  // The axis each echo direction points along (from the transducer towards the face).
  constexpr std::array<BeamFreeGrid::Direction, 4> kDirections{
      BeamFreeGrid::kWest, BeamFreeGrid::kEast, BeamFreeGrid::kSouth, BeamFreeGrid::kNorth};
  constexpr std::array<std::array<int, 2>, 4> kAxis{{{-1, 0}, {1, 0}, {0, -1}, {0, 1}}};
  // How far along each axis the farthest cell of `other` lies.
  std::array<int, 4> farthest;
  farthest.fill(std::numeric_limits<int>::min());
  for (const Eigen::Vector2i& c : other)
    for (std::size_t d = 0; d < 4; ++d)
      farthest[d] = std::max(farthest[d], kAxis[d][0] * c.x() + kAxis[d][1] * c.y());
  int facing = 0;
  for (const Eigen::Vector2i& c : faces)
    for (std::size_t d = 0; d < 4; ++d) {
      const int here = kAxis[d][0] * c.x() + kAxis[d][1] * c.y();
      if (farthest[d] < here - 1) facing += beam_free.Echoes(c.x(), c.y(), kDirections[d]);
    }
  return facing;
}

std::vector<std::vector<Eigen::Vector2i>> ClustersHeardApart(
    const std::vector<Eigen::Vector2i>& cells, int max_gap, const BeamFreeGrid& beam_free,
    int min_echoes) {
  if (min_echoes < 1) throw std::invalid_argument("min_echoes: must be >= 1");
  const std::vector<std::vector<Eigen::Vector2i>> groups = ClustersWithinGap(cells, max_gap);
  const std::size_t n = groups.size();
  std::vector<char> apart(n * n, 0);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      apart[a * n + b] = apart[b * n + a] =
          EchoesFacing(groups[a], groups[b], beam_free) >= min_echoes ||
          EchoesFacing(groups[b], groups[a], beam_free) >= min_echoes;
  // Greedy: each group joins the first set none of whose groups it was heard apart from.
  std::vector<std::vector<std::size_t>> sets;
  std::vector<int> set_of(n, -1);
  for (std::size_t g = 0; g < n; ++g) {
    for (std::size_t s = 0; s < sets.size() && set_of[g] < 0; ++s)
      if (std::none_of(sets[s].begin(), sets[s].end(),
                       [&](std::size_t h) { return apart[g * n + h] != 0; })) {
        sets[s].push_back(g);
        set_of[g] = static_cast<int>(s);
      }
    if (set_of[g] < 0) {
      set_of[g] = static_cast<int>(sets.size());
      sets.push_back({g});
    }
  }
  // Cells in input order; a repeated cell goes with its first copy's group.
  std::map<std::pair<int, int>, int> set_at;
  for (std::size_t g = 0; g < n; ++g)
    for (const Eigen::Vector2i& c : groups[g]) set_at.try_emplace({c.x(), c.y()}, set_of[g]);
  std::vector<std::vector<Eigen::Vector2i>> out(sets.size());
  for (const Eigen::Vector2i& c : cells)
    out[static_cast<std::size_t>(set_at.at({c.x(), c.y()}))].push_back(c);
  // Set ids follow the groups, which come in the order of their first cell: so do the sets.
  return out;
}

}  // namespace plywood::perception
