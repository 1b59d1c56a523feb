#pragma once

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "render/image_ops.h"
#include "render/png_image.h"
#include "render/world_to_pixel.h"

namespace plywood::render {

// Software drawing on top of a rendered (or fallback) top-down picture. Pixel-space functions take
// continuous image coordinates (see WorldToPixel: pixel (i, j) has its centre at (i + .5, j + .5));
// world-space functions map through a WorldToPixel first. Edges are anti-aliased over one pixel:
// a pixel whose centre lies at least half a pixel inside a shape is painted fully.

namespace colours {
inline constexpr Rgb kBlack{0, 0, 0};
inline constexpr Rgb kWhite{255, 255, 255};
inline constexpr Rgb kRed{220, 30, 30};
inline constexpr Rgb kGreen{20, 160, 40};
inline constexpr Rgb kBlue{30, 80, 220};
inline constexpr Rgb kOrange{240, 140, 0};
inline constexpr Rgb kMagenta{200, 40, 200};
inline constexpr Rgb kCyan{0, 170, 190};
// Distinct colours for estimates drawn beside the black ground truth, in order of use.
inline constexpr Rgb kPalette[] = {kRed, kBlue, kGreen, kOrange, kMagenta, kCyan};
}  // namespace colours

// A polyline through `points_px` (round joins and caps), `width_px` wide. Overlapping parts of the
// same polyline are painted once, so translucent joints do not darken.
void DrawPolylinePx(RgbImage& image, std::span<const Eigen::Vector2d> points_px, Rgb colour,
                    double width_px);
// A filled disc.
void FillCirclePx(RgbImage& image, const Eigen::Vector2d& centre_px, double radius_px, Rgb colour);
// A ring of `width_px` centred on the circle of `radius_px`.
void DrawCirclePx(RgbImage& image, const Eigen::Vector2d& centre_px, double radius_px, Rgb colour,
                  double width_px);
// A filled simple polygon (even-odd rule, sampled at pixel centres; not anti-aliased).
void FillPolygonPx(RgbImage& image, std::span<const Eigen::Vector2d> vertices_px, Rgb colour);
// An axis-aligned filled rectangle of whole pixels [x0, x1) x [y0, y1).
void FillRectPx(RgbImage& image, int x0, int y0, int x1, int y1, Rgb colour, double alpha = 1.0);

// World-space overlays: lengths in metres become pixels through `map`; line widths stay in pixels
// so thin lines remain visible in large worlds.
void DrawPolyline(RgbImage& image, const WorldToPixel& map,
                  std::span<const Eigen::Vector2d> points_W, Rgb colour, double width_px);
void DrawSegment(RgbImage& image, const WorldToPixel& map, const Eigen::Vector2d& a_W,
                 const Eigen::Vector2d& b_W, Rgb colour, double width_px);
void DrawPoint(RgbImage& image, const WorldToPixel& map, const Eigen::Vector2d& p_W, Rgb colour,
               double radius_px);
void DrawCircle(RgbImage& image, const WorldToPixel& map, const Eigen::Vector2d& centre_W,
                double radius_m, Rgb colour, double width_px);
// A pose marker: an isosceles triangle `length_px` long at (x, y) pointing along `theta_rad`.
void DrawPoseMarker(RgbImage& image, const WorldToPixel& map, const Eigen::Vector2d& p_W,
                    double theta_rad, Rgb colour, double length_px);

// A path to draw over a snapshot: ground truth in black, each estimate in its own colour.
struct PathOverlay {
  std::string label;                      // legend text; empty = not in the legend
  std::vector<Eigen::Vector2d> points_W;  // positions in the world frame, metres
  Rgb colour = colours::kBlack;
  double width_px = 2.0;
};

// Draws each path in order (later ones on top) with a dot at its start and a ring at its end.
void DrawPaths(RgbImage& image, const WorldToPixel& map, std::span<const PathOverlay> paths);

struct LegendEntry {
  std::string label;
  Rgb colour;
};
enum class Corner { kTopLeft, kTopRight, kBottomLeft, kBottomRight };

// A white box with a coloured swatch and a label per entry, `margin_px` from `corner`. Returns the
// box as [x0, x1) x [y0, y1) in pixels (all zero when `entries` is empty).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
PixelRect DrawLegend(RgbImage& image, std::span<const LegendEntry> entries,
                     Corner corner = Corner::kTopRight, int text_scale = 2, int margin_px = 8);

// The legend entries of the labelled paths, in order.
std::vector<LegendEntry> LegendFor(std::span<const PathOverlay> paths);

}  // namespace plywood::render
