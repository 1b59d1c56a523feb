#pragma once

#include <memory>
#include <vector>

#include "eval/sonar_map/sonar_ground_truth.h"

namespace plywood::eval {

// The cells of `set` (width x height, row-major) that some axis-aligned square of side_cells x
// side_cells cells, all of them in `set`, covers: the morphological opening of `set` by that
// square. Gaps and slivers narrower than the square drop out; right-angled corners stay.
std::vector<char> CellsASquareCovers(const std::vector<char>& set, int width, int height,
                                     int side_cells);

// `truth` with the free space no free square of the body's width covers left unscored: the gaps
// narrower than the robot between a box and a wall or between two boxes, which seed 001's method
// keeps obstacle ("gaps narrower than the robot stay obstacle", issue 14) while the world has them
// free. Neither call is blamed there. The rest, the room's corners included, is scored as by e,
// and the scored box is truth's. The square is axis-aligned, as the seed's rooms and rectangles
// are: a slanted gap is measured across its axis-aligned extent.
std::unique_ptr<OccupancyTruth> MakeTruthWithoutNarrowGaps(const OccupancyTruth& truth,
                                                           double body_width_m);

}  // namespace plywood::eval
