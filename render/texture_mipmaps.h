#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace plywood::render {

// Whether `n` is a power of two (1, 2, 4, ...).
bool IsPowerOfTwo(int n);

// The mipmap levels 1, 2, ... (down to 1 x 1) of a `width` x `height` RGB texture (3 bytes per
// texel, rows bottom-up as GL takes them, no padding) whose sides are powers of two, byte for byte
// what Mesa's llvmpipe (22.x) gives for glGenerateMipmap: each texel of a level is the bilinear
// sample half-way between the 2 x 2 texels of the level above, i.e. per channel
// Half(Half(a, b), Half(c, d)) with Half(p, q) = (256 p + 128 (q - p) + 128) >> 8 (its 8-bit
// fixed-point lerp; a side already 1 texel long repeats its texel). Computing them here spares
// llvmpipe's compilation of its blit shader (~0.43G instructions in every process that draws a
// snapshot); render/texture_mipmaps_test.cc checks them against glGenerateMipmap itself.
// @throws std::invalid_argument when a side is not a power of two or `rgb` has the wrong size.
std::vector<std::vector<std::uint8_t>> MipmapChain(std::span<const std::uint8_t> rgb, int width,
                                                   int height);

}  // namespace plywood::render
