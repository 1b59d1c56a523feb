#include "perception/sonar_map/contact_clearance.h"

#include <algorithm>

#include "perception/sonar_map/cell_dilation.h"

namespace plywood::perception {

std::vector<char> BlockedCells(const std::vector<char>& heard, const std::vector<char>& touched,
                               int width, int height, double clearance_cells,
                               double contact_clearance_cells) {
  if (contact_clearance_cells <= 0.0) {
    std::vector<char> both = heard;
    for (std::size_t i = 0; i < both.size(); ++i) both[i] = both[i] || touched[i];
    return Dilate(both, width, height, clearance_cells);
  }
  std::vector<char> blocked = Dilate(heard, width, height, clearance_cells);
  const std::vector<char> near_contact =
      Dilate(touched, width, height, std::min(clearance_cells, contact_clearance_cells));
  for (std::size_t i = 0; i < blocked.size(); ++i) blocked[i] = blocked[i] || near_contact[i];
  return blocked;
}

}  // namespace plywood::perception
