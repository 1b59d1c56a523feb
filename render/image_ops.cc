#include "render/image_ops.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace plywood::render {

RgbImage FromBottomUpRows(std::span<const std::uint8_t> rgb_bottom_up, int width, int height) {
  if (width <= 0 || height <= 0) {
    throw std::invalid_argument("width, height: must be > 0, got " + std::to_string(width) + " x " +
                                std::to_string(height));
  }
  const std::size_t row_bytes = static_cast<std::size_t>(width) * 3;
  if (rgb_bottom_up.size() != row_bytes * height) {
    throw std::invalid_argument("rgb_bottom_up: expected " + std::to_string(row_bytes * height) +
                                " bytes, got " + std::to_string(rgb_bottom_up.size()));
  }
  RgbImage image(width, height);
  for (int y = 0; y < height; ++y) {
    std::memcpy(image.At(0, y), rgb_bottom_up.data() + row_bytes * (height - 1 - y), row_bytes);
  }
  return image;
}

void Fill(RgbImage& image, Rgb colour) {
  const std::size_t whole_pixels = image.pixels.size() / 3 * 3;
  if (colour.r == colour.g && colour.g == colour.b) {  // grey or white: one byte value throughout
    std::fill_n(image.pixels.begin(), whole_pixels, colour.r);
    return;
  }
  for (std::size_t i = 0; i + 2 < image.pixels.size(); i += 3) {
    image.pixels[i] = colour.r;
    image.pixels[i + 1] = colour.g;
    image.pixels[i + 2] = colour.b;
  }
}

void BlendPixel(RgbImage& image, int x, int y, Rgb colour, double alpha) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height || !(alpha > 0.0)) return;
  std::uint8_t* p = image.At(x, y);
  if (alpha >= 1.0) {
    p[0] = colour.r;
    p[1] = colour.g;
    p[2] = colour.b;
    return;
  }
  const auto mix = [alpha](std::uint8_t under, std::uint8_t over) {
    // lround's result (halves away from zero) for this non-negative value, without the library
    // call: the fraction v - trunc(v) is exact. A replay blends ~10^6 pixels.
    const double v = under + alpha * (over - under);
    if (!(v >= 0.0)) return static_cast<std::uint8_t>(std::lround(v));
    const auto whole = static_cast<int>(v);
    return static_cast<std::uint8_t>(v - whole >= 0.5 ? whole + 1 : whole);
  };
  p[0] = mix(p[0], colour.r);
  p[1] = mix(p[1], colour.g);
  p[2] = mix(p[2], colour.b);
}

Rgb PixelAt(const RgbImage& image, int x, int y) {
  const std::uint8_t* p = image.At(x, y);
  return {p[0], p[1], p[2]};
}

}  // namespace plywood::render
