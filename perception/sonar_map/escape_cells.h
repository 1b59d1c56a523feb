#pragma once

#include <Eigen/Core>
#include <vector>

namespace plywood::perception {

// A robot can come to stand closer to something than its paths' clearance: a blocked move, a
// bump's back-off, a narrow passage, a face first heard from close by. The planner then lets it use
// the free cells around it so that it can leave. Leaving means getting no nearer: the cells it may
// use are those no nearer to a blocking cell than its own cell is. Letting it use every free cell
// near it (the rule before) sent a string-pulled path 0.19 m past a box corner the robot was
// standing 0.32 m from (layout 3, seed 18: a bumper contact). Distances are between cell centres,
// in cells, compared squared, so the answer is exact.

// Squared distance (in cells) from cell (ix, iy) to the nearest set cell of `blocked` whose centre
// lies within radius_cells of it; -1 when none does (the cell keeps that clearance).
int NearestBlockedDistance2(const std::vector<char>& blocked, int width, int height, int ix, int iy,
                            double radius_cells);

// The cells of `around` (free cells near the robot, width x height, row-major) whose nearest
// blocking cell within radius_cells is no nearer than the robot's cell `start`'s. When nothing
// blocking lies within radius_cells of `start`, the robot keeps the clearance already and only
// cells that keep it too are returned.
std::vector<char> EscapeCells(const std::vector<char>& around, const std::vector<char>& blocked,
                              int width, int height, const Eigen::Vector2i& start,
                              double radius_cells);

}  // namespace plywood::perception
