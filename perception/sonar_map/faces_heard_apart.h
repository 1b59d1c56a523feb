#pragma once

#include <Eigen/Core>
#include <vector>

#include "perception/sonar_map/beam_free_grid.h"

namespace plywood::perception {

// Echoes (BeamFreeGrid::Echoes) in the cells of `faces` whose transducer stood on the side of the
// echo's cell where every cell of `other` lies, more than a cell nearer it along the axis than
// the echo's cell (the echo's own cell and the range noise, a cell, stay out). A box's faces all
// lie at or beyond any face of it heard head-on, as seen from where that face was heard, so such
// echoes say `other` is something else: the robot stood between the two, facing `faces`.
int EchoesFacing(const std::vector<Eigen::Vector2i>& faces,
                 const std::vector<Eigen::Vector2i>& other, const BeamFreeGrid& beam_free);

// The cells as groups more than `max_gap` cells apart (ClustersWithinGap), joined again unless a
// face heard in one faces the other: two groups stay apart when at least `min_echoes` echoes of
// either face the other (EchoesFacing). Groups are joined greedily in their order (a group joins
// the first earlier set none of whose groups it is heard apart from), so groups heard apart never
// share a set. Sets come in the order of their first cell in `cells`, their cells in input order;
// one set when nothing was heard apart (one box seen from two sides: each face heard from outside,
// the unknown behind both).
std::vector<std::vector<Eigen::Vector2i>> ClustersHeardApart(
    const std::vector<Eigen::Vector2i>& cells, int max_gap, const BeamFreeGrid& beam_free,
    int min_echoes);

}  // namespace plywood::perception
