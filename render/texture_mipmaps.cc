#include "render/texture_mipmaps.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace plywood::render {
namespace {

// llvmpipe's 8-bit lerp at weight 1/2 (128 of 256), rounded.
int Half(int p, int q) { return (256 * p + 128 * (q - p) + 128) >> 8; }

}  // namespace

bool IsPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

std::vector<std::vector<std::uint8_t>> MipmapChain(std::span<const std::uint8_t> rgb, int width,
                                                   int height) {
  if (!IsPowerOfTwo(width) || !IsPowerOfTwo(height)) {
    throw std::invalid_argument("MipmapChain: sides must be powers of two, got " +
                                std::to_string(width) + " x " + std::to_string(height));
  }
  if (rgb.size() != static_cast<std::size_t>(width) * height * 3) {
    throw std::invalid_argument("MipmapChain: expected " + std::to_string(width * height * 3) +
                                " bytes, got " + std::to_string(rgb.size()));
  }
  std::vector<std::vector<std::uint8_t>> levels;
  levels.reserve(32);  // a level's bytes stay where `above` points when another is added
  std::span<const std::uint8_t> above = rgb;
  int w_above = width, h_above = height;
  while (w_above > 1 || h_above > 1) {
    const int w = std::max(1, w_above / 2), h = std::max(1, h_above / 2);
    std::vector<std::uint8_t> level(static_cast<std::size_t>(w) * h * 3);
    for (int y = 0; y < h; ++y) {
      const int y0 = std::min(2 * y, h_above - 1), y1 = std::min(2 * y + 1, h_above - 1);
      for (int x = 0; x < w; ++x) {
        const int x0 = std::min(2 * x, w_above - 1), x1 = std::min(2 * x + 1, w_above - 1);
        for (int k = 0; k < 3; ++k) {
          const auto at = [&](int xx, int yy) {
            return static_cast<int>(above[(static_cast<std::size_t>(yy) * w_above + xx) * 3 + k]);
          };
          level[(static_cast<std::size_t>(y) * w + x) * 3 + k] = static_cast<std::uint8_t>(
              Half(Half(at(x0, y0), at(x1, y0)), Half(at(x0, y1), at(x1, y1))));
        }
      }
    }
    levels.push_back(std::move(level));
    above = levels.back();
    w_above = w;
    h_above = h;
  }
  return levels;
}

}  // namespace plywood::render
