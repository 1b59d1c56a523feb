#include "perception/sonar_map/echo_passage.h"

#include <algorithm>
#include <stdexcept>

namespace plywood::perception {

std::vector<char> HeardWithoutAxisFreePaint(const std::vector<char>& heard,
                                            const BeamFreeGrid& beam_free, int min_passes,
                                            int keep_cells) {
  const int W = beam_free.width(), H = beam_free.height();
  if (heard.size() != static_cast<std::size_t>(W) * H)
    throw std::invalid_argument("heard: must have the beam-free grid's cells");
  // Cells holding an axis echo from any direction: the faces heard head-on.
  std::vector<char> echo(heard.size(), 0);
  for (int iy = 0; iy < H; ++iy)
    for (int ix = 0; ix < W; ++ix)
      for (const auto d :
           {BeamFreeGrid::kWest, BeamFreeGrid::kEast, BeamFreeGrid::kSouth, BeamFreeGrid::kNorth})
        if (beam_free.Echoes(ix, iy, d) > 0) echo[static_cast<std::size_t>(iy) * W + ix] = 1;
  std::vector<char> out = heard;
  for (int iy = 0; iy < H; ++iy)
    for (int ix = 0; ix < W; ++ix) {
      const std::size_t i = static_cast<std::size_t>(iy) * W + ix;
      if (!heard[i] || beam_free.Passes(ix, iy) < min_passes) continue;
      bool near_echo = false;
      for (int dy = -keep_cells; dy <= keep_cells && !near_echo; ++dy)
        for (int dx = -keep_cells; dx <= keep_cells && !near_echo; ++dx) {
          const int nx = ix + dx, ny = iy + dy;
          near_echo = nx >= 0 && ny >= 0 && nx < W && ny < H &&
                      echo[static_cast<std::size_t>(ny) * W + nx] != 0;
        }
      if (!near_echo) out[i] = 0;
    }
  return out;
}

}  // namespace plywood::perception
