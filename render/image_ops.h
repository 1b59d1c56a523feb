#pragma once

#include <cstdint>
#include <span>

#include "render/png_image.h"

namespace plywood::render {

// An 8-bit RGB colour.
struct Rgb {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

// OpenGL's glReadPixels (and so mjr_readPixels) returns rows bottom-up; RgbImage is top-down.
// `rgb_bottom_up` holds width * height * 3 bytes, its first row being the bottom of the picture.
// @throws std::invalid_argument when the size does not match.
RgbImage FromBottomUpRows(std::span<const std::uint8_t> rgb_bottom_up, int width, int height);

// Sets every pixel of `image` to `colour`.
void Fill(RgbImage& image, Rgb colour);

// Blends `colour` over pixel (x, y) with opacity `alpha` in [0, 1]; pixels outside are ignored so
// callers may draw shapes that leave the picture.
void BlendPixel(RgbImage& image, int x, int y, Rgb colour, double alpha = 1.0);

// The colour of pixel (x, y). @pre 0 <= x < width, 0 <= y < height.
Rgb PixelAt(const RgbImage& image, int x, int y);

}  // namespace plywood::render
