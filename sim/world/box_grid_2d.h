#pragma once

#include <cstdint>
#include <vector>

namespace plywood::sim {

// A uniform grid over axis-aligned boxes on the floor plane, built once: each box is listed in
// every cell it touches, so a query looks only at the boxes in the cells under its own box and
// its cost does not grow with the number of boxes elsewhere in the world.
class BoxGrid2D {
 public:
  struct Box {
    double lo[2], hi[2];
  };

  // `boxes` (lo <= hi, finite) in cells of cell_m (> 0) metres, grown until the grid has at most
  // max_cells cells. No boxes gives an empty grid.
  // @throws std::invalid_argument when cell_m or max_cells is not positive or a box is not finite
  // with lo <= hi.
  BoxGrid2D(std::vector<Box> boxes, double cell_m, int max_cells = 1 << 20);

  // The indices, ascending, of the boxes that meet `query` (closed boxes: touching counts): the
  // same set a test of every box gives. Reuses `out`'s storage. Not thread-safe: it marks the
  // boxes it has seen.
  void Query(const Box& query, std::vector<int>* out) const;

  int num_cells_x() const { return nx_; }
  int num_cells_y() const { return ny_; }
  double cell_m() const { return cell_m_; }

 private:
  // The cell range under [lo, hi] along axis k, clamped to the grid; false when it misses it.
  bool CellRange(double lo, double hi, int k, int* first, int* last) const;

  std::vector<Box> boxes_;
  double origin_[2] = {0.0, 0.0};
  double cell_m_ = 1.0, inv_cell_ = 1.0;
  int nx_ = 0, ny_ = 0;
  std::vector<uint32_t> cell_begin_;  // CSR: boxes of cell c are items_[begin[c]..begin[c+1])
  std::vector<uint32_t> items_;
  mutable std::vector<uint32_t> stamp_;  // by box: the query that last saw it
  mutable uint32_t epoch_ = 0;
};

}  // namespace plywood::sim
