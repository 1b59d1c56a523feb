#pragma once

#include <Eigen/Core>
#include <vector>

#include "perception/sonar_map/beam_free_grid.h"

namespace plywood::perception {

// The cells as sets, as ClustersHeardApart gives them, but grouped by the well-painted cells
// only: those at least `min_votes` readings called occupied (`votes[i]` for `cells[i]`), joined
// when at most `max_gap` cells lie between them (ClustersWithinGap) and kept apart where a face
// heard in one group faces the other (at least `min_echoes` echoes, EchoesFacing). Every other cell
// goes with the set of the nearest well-painted cell (the first of equally near ones). The sonar
// network paints its whole +-0.7 m window from every reading, so the unseen gap between two boxes
// gets occupied cells from a few far readings; that blur joins the two boxes' faces closer than
// obstacle_join_m, where the faces and a box's inside, painted by many readings, keep a gap. One
// set (all the cells) when fewer than two sets of well-painted cells are heard apart. Sets come in
// the order of their first cell in `cells`, their cells in input order.
std::vector<std::vector<Eigen::Vector2i>> ClustersOfWellPaintedCellsHeardApart(
    const std::vector<Eigen::Vector2i>& cells, const std::vector<int>& votes, int min_votes,
    int max_gap, const BeamFreeGrid& beam_free, int min_echoes);

}  // namespace plywood::perception
