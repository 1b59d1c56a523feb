#include "perception/sonar_map/unknown_share.h"

#include <cstddef>

namespace plywood::perception {

double UnknownShareOfRoom(const CellMap& cells, const LogOddsGrid& grid, const Rect& room) {
  long inside = 0, unknown = 0;
  for (int iy = 0; iy < grid.height(); ++iy)
    for (int ix = 0; ix < grid.width(); ++ix) {
      if (!room.Contains(grid.CellCentre(ix, iy))) continue;
      ++inside;
      if (cells.cells[static_cast<std::size_t>(iy) * grid.width() + ix] == CellState::kUnknown)
        ++unknown;
    }
  return inside > 0 ? static_cast<double>(unknown) / static_cast<double>(inside) : 0.0;
}

}  // namespace plywood::perception
