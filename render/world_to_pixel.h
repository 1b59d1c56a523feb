#pragma once

#include <Eigen/Core>

namespace plywood::render {

// An axis-aligned rectangle on the floor plane, in world metres.
struct WorldBounds {
  double x_min_m = 0.0;
  double x_max_m = 0.0;
  double y_min_m = 0.0;
  double y_max_m = 0.0;

  static WorldBounds Empty();
  bool IsEmpty() const { return !(x_max_m >= x_min_m && y_max_m >= y_min_m); }
  double width_m() const { return x_max_m - x_min_m; }
  double height_m() const { return y_max_m - y_min_m; }
  Eigen::Vector2d centre() const { return {0.5 * (x_min_m + x_max_m), 0.5 * (y_min_m + y_max_m)}; }
  void Extend(const Eigen::Vector2d& p_W);
  void Extend(const WorldBounds& other);
  // Grows every side by `margin_m`.
  WorldBounds Padded(double margin_m) const;
};

// The affine map between the floor plane (world x, y in metres) and continuous image coordinates
// (u right, v down, in pixels) of a top-down picture: world +x points right, world +y points up.
// Pixel (i, j) covers u in [i, i + 1), v in [j, j + 1), so its centre is (i + 0.5, j + 0.5).
struct WorldToPixel {
  double pixels_per_m = 1.0;
  double x_left_m = 0.0;  // world x at u = 0 (the picture's left edge)
  double y_top_m = 0.0;   // world y at v = 0 (the picture's top edge)

  Eigen::Vector2d ToPixel(const Eigen::Vector2d& p_W) const {
    return {(p_W.x() - x_left_m) * pixels_per_m, (y_top_m - p_W.y()) * pixels_per_m};
  }
  Eigen::Vector2d ToWorld(const Eigen::Vector2d& uv) const {
    return {x_left_m + uv.x() / pixels_per_m, y_top_m - uv.y() / pixels_per_m};
  }
};

// The picture size and mapping that show `bounds` with `longer_side_px` pixels along its longer
// side, at equal scale in x and y. The shorter side is rounded to whole pixels and the bounds are
// widened symmetrically so the map stays exact.
// @throws std::invalid_argument when `bounds` is empty or degenerate or `longer_side_px` < 2.
struct TopDownFrame {
  int width_px = 0;
  int height_px = 0;
  WorldToPixel world_to_pixel;
  WorldBounds shown;  // the floor rectangle the whole picture covers
};
TopDownFrame FrameBounds(const WorldBounds& bounds, int longer_side_px);

}  // namespace plywood::render
