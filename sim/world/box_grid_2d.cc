#include "sim/world/box_grid_2d.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace plywood::sim {

BoxGrid2D::BoxGrid2D(std::vector<Box> boxes, double cell_m, int max_cells)
    : boxes_(std::move(boxes)), cell_m_(cell_m) {
  if (!(cell_m > 0.0) || !std::isfinite(cell_m)) {
    throw std::invalid_argument("BoxGrid2D: cell_m must be > 0 and finite");
  }
  if (max_cells < 1) throw std::invalid_argument("BoxGrid2D: max_cells must be >= 1");
  if (boxes_.empty()) {
    cell_begin_.assign(1, 0);
    return;
  }
  double hi[2] = {-INFINITY, -INFINITY};
  origin_[0] = origin_[1] = INFINITY;
  for (const Box& b : boxes_) {
    for (int k = 0; k < 2; ++k) {
      if (!std::isfinite(b.lo[k]) || !std::isfinite(b.hi[k]) || !(b.lo[k] <= b.hi[k])) {
        throw std::invalid_argument("BoxGrid2D: a box is not finite with lo <= hi");
      }
      origin_[k] = std::min(origin_[k], b.lo[k]);
      hi[k] = std::max(hi[k], b.hi[k]);
    }
  }
  // The cell of the largest hi, computed as CellRange computes cells, is the last: no box's cells
  // are clamped.
  const auto cells_along = [this](double extent) { return std::floor(extent * inv_cell_) + 1.0; };
  inv_cell_ = 1.0 / cell_m_;
  while (cells_along(hi[0] - origin_[0]) * cells_along(hi[1] - origin_[1]) > max_cells) {
    cell_m_ *= 2.0;
    inv_cell_ = 1.0 / cell_m_;
  }
  nx_ = static_cast<int>(cells_along(hi[0] - origin_[0]));
  ny_ = static_cast<int>(cells_along(hi[1] - origin_[1]));

  // Two passes (count, then fill) build the compressed per-cell lists.
  cell_begin_.assign(static_cast<size_t>(nx_) * ny_ + 1, 0);
  const auto for_each_cell = [this](const Box& b, auto&& visit) {
    int x0, x1, y0, y1;
    if (!CellRange(b.lo[0], b.hi[0], 0, &x0, &x1) || !CellRange(b.lo[1], b.hi[1], 1, &y0, &y1)) {
      return;
    }
    for (int iy = y0; iy <= y1; ++iy) {
      for (int ix = x0; ix <= x1; ++ix) visit(iy * nx_ + ix);
    }
  };
  for (const Box& b : boxes_) for_each_cell(b, [&](int c) { ++cell_begin_[c + 1]; });
  for (size_t c = 1; c < cell_begin_.size(); ++c) cell_begin_[c] += cell_begin_[c - 1];
  items_.resize(cell_begin_.back());
  std::vector<uint32_t> fill(cell_begin_.begin(), cell_begin_.end() - 1);
  for (size_t i = 0; i < boxes_.size(); ++i) {
    for_each_cell(boxes_[i], [&](int c) { items_[fill[c]++] = static_cast<uint32_t>(i); });
  }
  stamp_.assign(boxes_.size(), 0);
}

bool BoxGrid2D::CellRange(double lo, double hi, int k, int* first, int* last) const {
  const int n = k == 0 ? nx_ : ny_;
  // Cell indices are floor((v - origin) / cell); a box and a query that meet share the cell of
  // any common point, and floor and the arithmetic are monotonic, so they share a cell index.
  const double a = std::floor((lo - origin_[k]) * inv_cell_);
  const double b = std::floor((hi - origin_[k]) * inv_cell_);
  if (!(b >= 0.0) || !(a <= n - 1.0)) return false;
  *first = static_cast<int>(std::max(a, 0.0));
  *last = static_cast<int>(std::min(b, n - 1.0));
  return true;
}

void BoxGrid2D::Query(const Box& query, std::vector<int>* out) const {
  out->clear();
  int x0, x1, y0, y1;
  if (boxes_.empty() || !CellRange(query.lo[0], query.hi[0], 0, &x0, &x1) ||
      !CellRange(query.lo[1], query.hi[1], 1, &y0, &y1)) {
    return;
  }
  if (++epoch_ == 0) {
    std::fill(stamp_.begin(), stamp_.end(), 0);
    epoch_ = 1;
  }
  for (int iy = y0; iy <= y1; ++iy) {
    // A row's cells are consecutive in the compressed lists: one run of items.
    const int row = iy * nx_;
    for (uint32_t k = cell_begin_[row + x0], end = cell_begin_[row + x1 + 1]; k < end; ++k) {
      const uint32_t i = items_[k];
      if (stamp_[i] == epoch_) continue;
      stamp_[i] = epoch_;
      const Box& b = boxes_[i];
      if (b.lo[0] <= query.hi[0] && query.lo[0] <= b.hi[0] && b.lo[1] <= query.hi[1] &&
          query.lo[1] <= b.hi[1]) {
        out->push_back(static_cast<int>(i));
      }
    }
  }
  std::sort(out->begin(), out->end());
}

}  // namespace plywood::sim
