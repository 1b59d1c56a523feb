#include "perception/sonar_map/box_face_sides.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace plywood::perception {
namespace {

// Whether, beyond one side, the cells seen free hold a patch of the given size. `along` runs over
// the cells whose centres lie within the room's span along the side, `out` from the first cell
// beyond the side outwards; `seen(a, o)` says whether that cell was seen free. With gaps only,
// the line across the side at `a` counts only where `gap(a)` (no heard cell of the side's own
// there) and where the floor seen past the side does not end on a heard cell (`heard(a, o)`):
// such floor is the network painting a notch into a wall's thickness, with the wall's back
// heard behind it (issue 14 round 64b).
template <typename Seen, typename Gap, typename Heard>
bool PatchBeyond(int along_begin, int along_end, int out_cells, int length_cells, int depth_cells,
                 const Seen& seen, bool gaps_only, const Gap& gap, const Heard& heard) {
  int run = 0;
  for (int a = along_begin; a < along_end; ++a) {
    // This line across the side holds depth_cells consecutive cells seen free somewhere beyond.
    int deep = 0;
    int o = 0;
    for (; o < out_cells && deep < depth_cells; ++o) deep = seen(a, o) ? deep + 1 : 0;
    bool floor = deep >= depth_cells;
    if (gaps_only && floor) {
      while (o < out_cells && seen(a, o)) ++o;
      floor = gap(a) && !(o < out_cells && heard(a, o));
    }
    run = floor ? run + 1 : 0;
    if (run >= length_cells) return true;
  }
  return false;
}

RoomSides SidesSeenPastWhere(const CellMap& cells, const LogOddsGrid& grid,
                             const BeamFreeGrid* beam_free, int min_passes, const Rect& room,
                             double min_length_m, double min_depth_m, bool gaps_only) {
  const int W = grid.width(), H = grid.height();
  const double res = grid.resolution_m();
  const auto seen = [&](int ix, int iy) {
    if (ix < 0 || iy < 0 || ix >= W || iy >= H) return false;
    if (cells.cells[static_cast<std::size_t>(iy) * W + ix] == CellState::kFree) return true;
    return beam_free != nullptr && beam_free->Passes(ix, iy) >= min_passes;
  };
  const int length_cells = std::max(1, static_cast<int>(std::ceil(min_length_m / res - 1e-9)));
  // More than min_depth_m outwards: whole cells past it.
  const int depth_cells = std::max(1, static_cast<int>(std::floor(min_depth_m / res + 1e-9)) + 1);
  // The cells whose centres lie within the room's span along x and along y, and the first cell
  // whose centre lies beyond each side.
  int x_begin = W, x_end = 0, y_begin = H, y_end = 0, west = -1, east = W, south = -1, north = H;
  for (int ix = 0; ix < W; ++ix) {
    const double x = grid.CellCentre(ix, 0).x();
    if (x >= room.x0 && x <= room.x1) {
      x_begin = std::min(x_begin, ix);
      x_end = std::max(x_end, ix + 1);
    }
    if (x < room.x0) west = ix;
    if (x > room.x1) east = std::min(east, ix);
  }
  for (int iy = 0; iy < H; ++iy) {
    const double y = grid.CellCentre(0, iy).y();
    if (y >= room.y0 && y <= room.y1) {
      y_begin = std::min(y_begin, iy);
      y_end = std::max(y_end, iy + 1);
    }
    if (y < room.y0) south = iy;
    if (y > room.y1) north = std::min(north, iy);
  }
  const auto heard = [&](int ix, int iy) {
    return ix >= 0 && iy >= 0 && ix < W && iy < H &&
           cells.cells[static_cast<std::size_t>(iy) * W + ix] == CellState::kOccupied;
  };
  // A gap in the side at the line across it through cell `a` along it: no heard cell within two
  // cells of the side's line on either side of it (`first` is the first cell beyond the side,
  // `step` outwards).
  constexpr int kLineCells = 2;
  const auto gap = [&](int first, int step, bool side_along_y) {
    return [&heard, first, step, side_along_y](int a) {
      for (int o = -kLineCells; o < kLineCells; ++o) {
        const int across = first + step * o;
        if (side_along_y ? heard(across, a) : heard(a, across)) return false;
      }
      return true;
    };
  };
  RoomSides out;
  out.west = PatchBeyond(
      y_begin, y_end, west + 1, length_cells, depth_cells,
      [&](int a, int o) { return seen(west - o, a); }, gaps_only, gap(west, -1, true),
      [&](int a, int o) { return heard(west - o, a); });
  out.east = PatchBeyond(
      y_begin, y_end, W - east, length_cells, depth_cells,
      [&](int a, int o) { return seen(east + o, a); }, gaps_only, gap(east, 1, true),
      [&](int a, int o) { return heard(east + o, a); });
  out.south = PatchBeyond(
      x_begin, x_end, south + 1, length_cells, depth_cells,
      [&](int a, int o) { return seen(a, south - o); }, gaps_only, gap(south, -1, false),
      [&](int a, int o) { return heard(a, south - o); });
  out.north = PatchBeyond(
      x_begin, x_end, H - north, length_cells, depth_cells,
      [&](int a, int o) { return seen(a, north + o); }, gaps_only, gap(north, 1, false),
      [&](int a, int o) { return heard(a, north + o); });
  return out;
}

}  // namespace

RoomSides SidesSeenPast(const CellMap& cells, const LogOddsGrid& grid,
                        const BeamFreeGrid* beam_free, int min_passes, const Rect& room,
                        double min_length_m, double min_depth_m) {
  return SidesSeenPastWhere(cells, grid, beam_free, min_passes, room, min_length_m, min_depth_m,
                            false);
}

RoomSides SidesSeenPastThroughGaps(const CellMap& cells, const LogOddsGrid& grid,
                                   const BeamFreeGrid* beam_free, int min_passes, const Rect& room,
                                   double min_width_m, double min_depth_m) {
  return SidesSeenPastWhere(cells, grid, beam_free, min_passes, room, min_width_m, min_depth_m,
                            true);
}

Rect OpenSides(const Rect& room, const RoomSides& open, const LogOddsGrid& grid) {
  // The grid's outer edges: cell (0, 0)'s centre less half a cell, the last cell's plus half.
  const double half = 0.5 * grid.resolution_m();
  const Eigen::Vector2d low = grid.CellCentre(0, 0) - Eigen::Vector2d::Constant(half);
  const Eigen::Vector2d high =
      grid.CellCentre(grid.width() - 1, grid.height() - 1) + Eigen::Vector2d::Constant(half);
  return Rect{open.west ? std::min(room.x0, low.x()) : room.x0,
              open.south ? std::min(room.y0, low.y()) : room.y0,
              open.east ? std::max(room.x1, high.x()) : room.x1,
              open.north ? std::max(room.y1, high.y()) : room.y1};
}

}  // namespace plywood::perception
