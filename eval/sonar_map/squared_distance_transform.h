#pragma once

#include <vector>

namespace plywood::eval {

// The exact Euclidean distance transform of a grid, squared, in cells: for every cell, the squared
// distance from its centre to the centre of the nearest cell of `set` (row-major, `width` x
// `height`). Separable lower envelopes of parabolas (Felzenszwalb and Huttenlocher), linear in the
// number of cells, so it serves a 1 cm raster of a whole room, where stamping discs would not.
// Cells when `set` is empty: kNoSetCell.
inline constexpr double kNoSetCell = 1e20;
std::vector<double> SquaredDistanceToSet(const std::vector<char>& set, int width, int height);

}  // namespace plywood::eval
