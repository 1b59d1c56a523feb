#pragma once

#include <vector>

namespace plywood::perception {

// Where a path's centre may not go at a clearance tier: within clearance_cells of a cell the sonar
// heard (its face may lie anywhere in the cell, the beam's cone and the network's blur), and
// within min(clearance_cells, contact_clearance_cells) of a cell a bump panel touched. A contact
// point is exact to the body: the panel's arc places it within ~4 cm, so the body's own corridor
// (robot radius + front margin) keeps the robot off it, whereas a tier's clearance round it closed
// a gap the robot fits (generated world 46 of seed 22: a 0.61 m gap between two box corners, one
// never heard, closed for good by the contact at it). contact_clearance_cells <= 0: a contact
// blocks like a heard cell. Distances are between cell centres (Dilate).
std::vector<char> BlockedCells(const std::vector<char>& heard, const std::vector<char>& touched,
                               int width, int height, double clearance_cells,
                               double contact_clearance_cells);

}  // namespace plywood::perception
