#pragma once

#include <vector>

#include "perception/sonar_map/beam_free_grid.h"

namespace plywood::perception {

// A passage whose mouth the sonar network paints narrower than it is. The network blurs a box
// corner outwards by a few centimetres on every side, so a 0.62-0.65 m passage between two corners
// is heard below the 0.60 m the squeeze clearance (2 x 0.30 m) needs, and the space behind it is
// never entered (issue 14, generated seed 22: 4-5 m^2 per room). The grid-aligned sonar axes
// (BeamFreeGrid) measure such a mouth better: an axis that passed through a cell saw it free up to
// its echo, and the faces it heard head-on sit where the echoes are.

// The cells of `heard` (occupied, width x height of `beam_free`, row-major) that stay when the
// network's paint the axes saw through is dropped: a cell at least min_passes axes passed through
// is dropped unless an axis echo lies in a cell within keep_cells of it (Chebyshev distance, in
// cells), i.e. unless a face was heard head-on there. Cells the axes never passed stay, so
// a face heard only by oblique sonars, or a corner no axis came near, keeps its painted cells.
std::vector<char> HeardWithoutAxisFreePaint(const std::vector<char>& heard,
                                            const BeamFreeGrid& beam_free, int min_passes,
                                            int keep_cells);

}  // namespace plywood::perception
