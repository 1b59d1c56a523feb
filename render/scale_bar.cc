#include "render/scale_bar.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "render/bitmap_font.h"
#include "render/overlay.h"

namespace plywood::render {

double NiceScaleLengthM(double span_m) {
  const double target = span_m / 5.0;
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  for (const double step : {5.0, 2.0, 1.0}) {
    if (step * decade <= target) return step * decade;
  }
  return decade;
}

void DrawScaleBarAndAxes(RgbImage& image, const WorldToPixel& map) {
  const double span_m = std::max(image.width, image.height) / map.pixels_per_m;
  const double length_m = NiceScaleLengthM(span_m);
  const double length_px = length_m * map.pixels_per_m;
  const int text_scale = image.width >= 800 ? 2 : 1;

  // Axes from the world origin, when it is in the picture.
  const Eigen::Vector2d origin_px = map.ToPixel({0.0, 0.0});
  if (origin_px.x() >= 0 && origin_px.y() >= 0 && origin_px.x() < image.width &&
      origin_px.y() < image.height) {
    const Eigen::Vector2d x_end = origin_px + Eigen::Vector2d(length_px, 0.0);
    const Eigen::Vector2d y_end = origin_px - Eigen::Vector2d(0.0, length_px);
    const Eigen::Vector2d x_axis[] = {origin_px, x_end};
    const Eigen::Vector2d y_axis[] = {origin_px, y_end};
    DrawPolylinePx(image, x_axis, colours::kRed, 2.0);
    DrawPolylinePx(image, y_axis, colours::kGreen, 2.0);
    DrawText(image, static_cast<int>(x_end.x()) + 3, static_cast<int>(x_end.y()) - 3, "x",
             colours::kRed, text_scale);
    DrawText(image, static_cast<int>(y_end.x()) + 3, static_cast<int>(y_end.y()) - 3, "y",
             colours::kGreen, text_scale);
  }

  // The bar on a white box in the bottom-left corner, labelled with its length.
  char label[32];
  std::snprintf(label, sizeof(label), "%g m", length_m);
  const int margin = 8, pad = 4;
  const int box_w = static_cast<int>(std::ceil(length_px)) + 2 * pad;
  const int box_h = TextHeightPx(text_scale) + 6 + 3 * pad;
  const int x0 = margin, y1 = image.height - margin, y0 = y1 - box_h;
  const int box_w_text = std::max(box_w, TextWidthPx(label, text_scale) + 2 * pad);
  FillRectPx(image, x0, y0, x0 + box_w_text, y1, colours::kWhite, 0.85);
  const double bar_y = y1 - pad - 3.0;
  const Eigen::Vector2d bar[] = {{x0 + pad, bar_y}, {x0 + pad + length_px, bar_y}};
  DrawPolylinePx(image, bar, colours::kBlack, 4.0);
  DrawText(image, x0 + pad, y0 + pad, label, colours::kBlack, text_scale);
}

}  // namespace plywood::render
