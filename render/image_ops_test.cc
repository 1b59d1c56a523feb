#include "render/image_ops.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace plywood::render {
namespace {

TEST(FromBottomUpRowsTest, FirstInputRowBecomesBottomRow) {
  // 2 x 3 image; each pixel's red byte encodes its input row, green its column.
  const int width = 2, height = 3;
  std::vector<std::uint8_t> rgb;
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      rgb.insert(rgb.end(), {static_cast<std::uint8_t>(row), static_cast<std::uint8_t>(col), 7});
    }
  }
  const RgbImage image = FromBottomUpRows(rgb, width, height);
  ASSERT_EQ(image.width, width);
  ASSERT_EQ(image.height, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      EXPECT_EQ(PixelAt(image, x, y),
                (Rgb{static_cast<std::uint8_t>(height - 1 - y), static_cast<std::uint8_t>(x), 7}))
          << "x=" << x << " y=" << y;
    }
  }
}

TEST(FromBottomUpRowsTest, RejectsWrongSize) {
  std::vector<std::uint8_t> rgb(2 * 2 * 3 - 1);
  EXPECT_THROW(FromBottomUpRows(rgb, 2, 2), std::invalid_argument);
  EXPECT_THROW(FromBottomUpRows(rgb, 0, 2), std::invalid_argument);
}

TEST(BlendPixelTest, BlendsLinearlyAndIgnoresOutside) {
  RgbImage image(2, 2);
  Fill(image, {100, 0, 200});
  BlendPixel(image, 1, 0, {200, 100, 0}, 0.5);
  EXPECT_EQ(PixelAt(image, 1, 0), (Rgb{150, 50, 100}));
  BlendPixel(image, 0, 1, {1, 2, 3});
  EXPECT_EQ(PixelAt(image, 0, 1), (Rgb{1, 2, 3}));
  BlendPixel(image, -1, 0, {1, 2, 3});
  BlendPixel(image, 0, 2, {1, 2, 3});
  EXPECT_EQ(PixelAt(image, 0, 0), (Rgb{100, 0, 200}));
}

// The blend rounds as std::lround (halves away from zero) for every pair of bytes, with alphas
// that land exactly on halves (0.5 of an odd difference) and that do not.
TEST(BlendPixelTest, RoundsEveryBlendAsLround) {
  const double alphas[] = {0.5, 0.25, 0.75, 0.1, 1.0 / 3.0, 0.999, 1e-9, 0.4999999999};
  RgbImage image(1, 1);
  for (double alpha : alphas) {
    for (int under = 0; under < 256; ++under) {
      for (int over = 0; over < 256; ++over) {
        const auto u = static_cast<std::uint8_t>(under), o = static_cast<std::uint8_t>(over);
        Fill(image, {u, u, u});
        BlendPixel(image, 0, 0, {o, o, o}, alpha);
        const long expected = std::lround(under + alpha * (over - under));
        ASSERT_EQ(PixelAt(image, 0, 0).r, expected) << under << " " << over << " " << alpha;
      }
    }
  }
}

// A grey fill (one byte value) and a coloured one write every pixel alike.
TEST(FillTest, GreyAndColouredFillsWriteEveryPixel) {
  RgbImage image(3, 2);
  Fill(image, {7, 7, 7});
  EXPECT_EQ(image.pixels, std::vector<std::uint8_t>(18, 7));
  Fill(image, {1, 2, 3});
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) EXPECT_EQ(PixelAt(image, x, y), (Rgb{1, 2, 3}));
}

}  // namespace
}  // namespace plywood::render
