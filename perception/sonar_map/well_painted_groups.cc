#include "perception/sonar_map/well_painted_groups.h"

#include <cstddef>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

#include "perception/sonar_map/faces_heard_apart.h"

namespace plywood::perception {

std::vector<std::vector<Eigen::Vector2i>> ClustersOfWellPaintedCellsHeardApart(
    const std::vector<Eigen::Vector2i>& cells, const std::vector<int>& votes, int min_votes,
    int max_gap, const BeamFreeGrid& beam_free, int min_echoes) {
  if (votes.size() != cells.size()) throw std::invalid_argument("votes: one count per cell needed");
  if (min_votes < 1) throw std::invalid_argument("min_votes: must be >= 1");
  std::vector<Eigen::Vector2i> well_painted;
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (votes[i] >= min_votes) well_painted.push_back(cells[i]);
  if (well_painted.size() < 2) return {cells};
  const std::vector<std::vector<Eigen::Vector2i>> sets =
      ClustersHeardApart(well_painted, max_gap, beam_free, min_echoes);
  if (sets.size() < 2) return {cells};
  std::map<std::pair<int, int>, std::size_t> set_at;
  for (std::size_t s = 0; s < sets.size(); ++s)
    for (const Eigen::Vector2i& c : sets[s]) set_at.try_emplace({c.x(), c.y()}, s);
  // The set of each cell: its own, or the nearest well-painted cell's.
  std::vector<std::size_t> set_of(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const auto it = set_at.find({cells[i].x(), cells[i].y()});
    if (it != set_at.end()) {
      set_of[i] = it->second;
      continue;
    }
    long best = std::numeric_limits<long>::max();
    for (const Eigen::Vector2i& w : well_painted) {
      const long dx = w.x() - cells[i].x(), dy = w.y() - cells[i].y();
      if (dx * dx + dy * dy < best) {
        best = dx * dx + dy * dy;
        set_of[i] = set_at.at({w.x(), w.y()});
      }
    }
  }
  // Sets renumbered by their first cell in `cells`.
  std::vector<int> order(sets.size(), -1);
  std::vector<std::vector<Eigen::Vector2i>> out;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    int& k = order[set_of[i]];
    if (k < 0) {
      k = static_cast<int>(out.size());
      out.emplace_back();
    }
    out[static_cast<std::size_t>(k)].push_back(cells[i]);
  }
  return out;
}

}  // namespace plywood::perception
