#include "render/world_to_pixel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace plywood::render {

WorldBounds WorldBounds::Empty() {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  return {kInf, -kInf, kInf, -kInf};
}

void WorldBounds::Extend(const Eigen::Vector2d& p_W) {
  x_min_m = std::min(x_min_m, p_W.x());
  x_max_m = std::max(x_max_m, p_W.x());
  y_min_m = std::min(y_min_m, p_W.y());
  y_max_m = std::max(y_max_m, p_W.y());
}

void WorldBounds::Extend(const WorldBounds& other) {
  if (other.IsEmpty()) return;
  Extend(Eigen::Vector2d(other.x_min_m, other.y_min_m));
  Extend(Eigen::Vector2d(other.x_max_m, other.y_max_m));
}

WorldBounds WorldBounds::Padded(double margin_m) const {
  return {x_min_m - margin_m, x_max_m + margin_m, y_min_m - margin_m, y_max_m + margin_m};
}

TopDownFrame FrameBounds(const WorldBounds& bounds, int longer_side_px) {
  if (longer_side_px < 2) {
    throw std::invalid_argument("longer_side_px: must be >= 2, got " +
                                std::to_string(longer_side_px));
  }
  if (bounds.IsEmpty() || !std::isfinite(bounds.width_m()) || !std::isfinite(bounds.height_m()) ||
      std::max(bounds.width_m(), bounds.height_m()) <= 0.0) {
    throw std::invalid_argument("bounds: must be a finite rectangle of positive size");
  }
  const double longer_m = std::max(bounds.width_m(), bounds.height_m());
  const double pixels_per_m = longer_side_px / longer_m;
  const int shorter_px = std::max(
      1, static_cast<int>(
             std::ceil(std::min(bounds.width_m(), bounds.height_m()) * pixels_per_m - 1e-9)));
  TopDownFrame frame;
  frame.width_px = bounds.width_m() >= bounds.height_m() ? longer_side_px : shorter_px;
  frame.height_px = bounds.width_m() >= bounds.height_m() ? shorter_px : longer_side_px;
  const Eigen::Vector2d centre = bounds.centre();
  const double half_w_m = 0.5 * frame.width_px / pixels_per_m;
  const double half_h_m = 0.5 * frame.height_px / pixels_per_m;
  frame.shown = {centre.x() - half_w_m, centre.x() + half_w_m, centre.y() - half_h_m,
                 centre.y() + half_h_m};
  frame.world_to_pixel = {pixels_per_m, frame.shown.x_min_m, frame.shown.y_max_m};
  return frame;
}

}  // namespace plywood::render
