#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace plywood::render {

// An 8-bit RGB image, rows top-down (row 0 is the top of the picture).
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // width * height * 3

  RgbImage() = default;
  RgbImage(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h * 3, 0) {}
  std::uint8_t* At(int x, int y) { return &pixels[(static_cast<std::size_t>(y) * width + x) * 3]; }
  const std::uint8_t* At(int x, int y) const {
    return &pixels[(static_cast<std::size_t>(y) * width + x) * 3];
  }
};

// Writes `image` as PNG under a temporary name beside `path` ("PATH.partial-PID") and renames it
// into place, so a failed write leaves no cut picture and an earlier one as it was; a device
// (/dev/full) is written to directly. @throws std::runtime_error naming `path` on failure.
void WritePng(const RgbImage& image, const std::filesystem::path& path);

// Reads an 8-bit RGB or RGBA PNG (alpha dropped). @throws std::runtime_error naming `path`.
RgbImage ReadPng(const std::filesystem::path& path);

}  // namespace plywood::render
