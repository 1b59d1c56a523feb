#pragma once

#include <filesystem>
#include <vector>

namespace plywood::eval {

// An occupancy grid as a picture: brightness per pixel in [0, 1] (0 black, 1 white), rows
// top-down as in the file.
struct GridImage {
  int width = 0;
  int height = 0;
  std::vector<double> brightness;  // width * height

  double At(int x, int y) const {
    return brightness[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                      static_cast<std::size_t>(x)];
  }
};

// Reads a PNG (libpng; 8 or 16 bits as stored, colour pixels the mean of R, G and B; an 8-bit
// alpha channel must be opaque in every pixel, a 16-bit one is refused) or a PGM, plain (P2) or
// raw (P5),
// maxval 1..65535, '#' comments in the header; the format is told by the first bytes, not the name.
// @throws sim::ConfigError "FILE[:LINE]: FIELD: what is wrong" for an unreadable, truncated or
// corrupt file, a bad PGM header field (magic, width, height, maxval) or sample (pixel N), or a
// PNG pixel that is not opaque (pixel N).
GridImage ReadGridImage(const std::filesystem::path& path);

}  // namespace plywood::eval
