#include "render/overlay.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "render/bitmap_font.h"

namespace plywood::render {
namespace {

constexpr Rgb kGrey{128, 128, 128};

int CountColour(const RgbImage& image, Rgb colour) {
  int n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) n += PixelAt(image, x, y) == colour;
  }
  return n;
}

TEST(OverlayTest, PolylinePaintsPixelsAlongItsSegmentsOnly) {
  RgbImage image(100, 100);
  Fill(image, kGrey);
  // World (0..10 m) at 10 px/m: an L from (1, 9) to (8, 9) to (8, 2), i.e. pixel rows/cols 10/80.
  const WorldToPixel map{10.0, 0.0, 10.0};
  const std::vector<Eigen::Vector2d> path_W = {{1.0, 9.0}, {8.0, 9.0}, {8.0, 2.0}};
  DrawPolyline(image, map, path_W, colours::kBlack, 3.0);
  // Horizontal leg on the line v = 10 (between pixel rows 9 and 10), u from 10 to 80.
  for (int x = 12; x <= 76; ++x) {  // stop clear of the vertical leg's band
    EXPECT_EQ(PixelAt(image, x, 9), colours::kBlack) << x;
    EXPECT_EQ(PixelAt(image, x, 10), colours::kBlack) << x;
    EXPECT_EQ(PixelAt(image, x, 13), kGrey) << x;  // 3 px wide: 1.5 px either side of v = 10
    EXPECT_EQ(PixelAt(image, x, 6), kGrey) << x;
  }
  // Vertical leg on u = 80, v from 10 to 80.
  for (int y = 12; y <= 78; ++y) {
    EXPECT_EQ(PixelAt(image, 79, y), colours::kBlack) << y;
    EXPECT_EQ(PixelAt(image, 80, y), colours::kBlack) << y;
    EXPECT_EQ(PixelAt(image, 83, y), kGrey) << y;
  }
  // Nothing inside the L or beyond its ends.
  EXPECT_EQ(PixelAt(image, 40, 40), kGrey);
  EXPECT_EQ(PixelAt(image, 5, 9), kGrey);
  EXPECT_EQ(PixelAt(image, 79, 85), kGrey);
  // Roughly the area of a 3 px wide band 140 px long.
  const int black = CountColour(image, colours::kBlack);
  EXPECT_GT(black, 2 * 140);
  EXPECT_LT(black, 4 * 140);
}

TEST(OverlayTest, OverlappingSegmentsOfOnePolylineBlendOnce) {
  RgbImage image(20, 20);
  Fill(image, colours::kWhite);
  // Back and forth over the same pixels: the anti-aliased edge must equal a single pass's.
  const std::vector<Eigen::Vector2d> once = {{2.0, 10.2}, {18.0, 10.2}};
  const std::vector<Eigen::Vector2d> twice = {{2.0, 10.2}, {18.0, 10.2}, {2.0, 10.2}};
  RgbImage a = image, b = image;
  DrawPolylinePx(a, once, colours::kBlack, 2.0);
  DrawPolylinePx(b, twice, colours::kBlack, 2.0);
  EXPECT_EQ(a.pixels, b.pixels);
}

// Every pixel of a drawn polyline is the blend of its distance from the nearest of the
// polyline's segments (one pixel ramp, the largest coverage once): checked pixel by pixel against
// that definition over the whole image, for segments steep and shallow, less than a pixel from
// horizontal, of no length, and partly or wholly off the image.
TEST(OverlayTest, EveryPixelIsPaintedByItsDistanceFromTheNearestSegment) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> coord(-20.0, 100.0), width(0.3, 4.0);
  const auto distance = [](const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                           const Eigen::Vector2d& b) {
    const Eigen::Vector2d ab = b - a;
    const double t =
        ab.squaredNorm() > 0.0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
    return (p - (a + t * ab)).norm();
  };
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Eigen::Vector2d> points;
    const int n = 1 + trial % 4;  // 1 point, 1, 2 and 3 segments
    for (int i = 0; i < n; ++i) points.emplace_back(coord(rng), coord(rng));
    if (trial % 5 == 1) points.back() = points.front() + Eigen::Vector2d(coord(rng), 0.3);
    if (trial % 7 == 2) points.back() = points.front();
    const double w = width(rng);
    RgbImage drawn(80, 70), expected(80, 70);
    Fill(drawn, colours::kWhite);
    Fill(expected, colours::kWhite);
    DrawPolylinePx(drawn, points, colours::kBlue, w);
    for (int y = 0; y < 70; ++y) {
      for (int x = 0; x < 80; ++x) {
        const Eigen::Vector2d p(x + 0.5, y + 0.5);
        float c = 0.0f;
        for (std::size_t i = 0; i + 1 < std::max<std::size_t>(points.size(), 2); ++i) {
          const Eigen::Vector2d& a = points[i];
          const Eigen::Vector2d& b = points[std::min(i + 1, points.size() - 1)];
          const double d = distance(p, a, b);
          c = std::max(c, static_cast<float>(std::clamp(0.5 * w + 0.5 - d, 0.0, 1.0)));
        }
        if (c > 0.0f) BlendPixel(expected, x, y, colours::kBlue, c);
      }
    }
    ASSERT_EQ(drawn.pixels, expected.pixels) << "trial " << trial << ", width " << w;
  }
}

// A shape reaching far off the image (an estimate that ran away: 1e12 or 1e300 px) still paints
// its visible part, as the same shape cut at the image's edge does.
TEST(OverlayTest, ShapesReachingFarOffTheImagePaintTheirVisiblePart) {
  for (const double far : {1e12, 1e300}) {
    RgbImage drawn(40, 20), cut(40, 20);
    Fill(drawn, colours::kWhite);
    Fill(cut, colours::kWhite);
    const std::vector<Eigen::Vector2d> to_far = {{10.0, 10.0}, {far, 10.0}};
    const std::vector<Eigen::Vector2d> to_edge = {{10.0, 10.0}, {45.0, 10.0}};
    DrawPolylinePx(drawn, to_far, colours::kBlack, 2.0);
    DrawPolylinePx(cut, to_edge, colours::kBlack, 2.0);
    EXPECT_EQ(drawn.pixels, cut.pixels) << far;
    EXPECT_EQ(PixelAt(drawn, 39, 9), colours::kBlack) << far;
    // A triangle with a vertex far to the left covers the rows it spans up to its right edge.
    RgbImage filled(40, 20);
    Fill(filled, colours::kWhite);
    const std::vector<Eigen::Vector2d> triangle = {{-far, 10.0}, {30.0, 2.0}, {30.0, 18.0}};
    FillPolygonPx(filled, triangle, colours::kBlack);
    EXPECT_EQ(PixelAt(filled, 29, 10), colours::kBlack) << far;
    EXPECT_EQ(PixelAt(filled, 0, 10), colours::kBlack) << far;
    EXPECT_EQ(PixelAt(filled, 31, 10), colours::kWhite) << far;
  }
}

// A line reaching far off the image at both ends (1e16 px and beyond: past 2^53 px a coordinate's
// rounding exceeds a pixel) paints where it crosses the image as the same line cut near the
// image does: through the whole segment's rounded nearest points it painted nothing or dashes.
TEST(OverlayTest, ALineFarOffTheImageAtBothEndsPaintsWhereItCrossesIt) {
  const auto draw = [](const std::vector<Eigen::Vector2d>& points, double width) {
    RgbImage image(40, 20);
    Fill(image, colours::kWhite);
    DrawPolylinePx(image, points, colours::kBlack, width);
    return image.pixels;
  };
  for (const double far : {1e16, 1e20, 1e300}) {
    EXPECT_EQ(draw({{-far, 10.3}, {far, 10.3}}, 2.0), draw({{-5.0, 10.3}, {45.0, 10.3}}, 2.0))
        << far;
  }
  for (const int exponent : {40, 60, 1000}) {  // y = x / 2, the image's diagonal
    const double far = std::ldexp(1.0, exponent);
    for (const double width : {0.7, 2.0, 5.5}) {
      const auto cut = draw({{-8.0, -4.0}, {48.0, 24.0}}, width);
      EXPECT_EQ(draw({{-far, -far / 2}, {far, far / 2}}, width), cut) << exponent << " " << width;
      EXPECT_EQ(draw({{-far, -far / 2}, {0.0, 0.0}, {far, far / 2}}, width), cut) << exponent;
    }
  }
}

TEST(OverlayTest, FilledCircleCoversItsArea) {
  RgbImage image(64, 64);
  Fill(image, kGrey);
  FillCirclePx(image, {32.0, 32.0}, 10.0, colours::kRed);
  EXPECT_EQ(PixelAt(image, 32, 32), colours::kRed);
  EXPECT_EQ(PixelAt(image, 32 + 8, 32), colours::kRed);
  EXPECT_EQ(PixelAt(image, 32 + 12, 32), kGrey);
  // Full pixels: those with centres within r - 0.5, about pi (r - 0.5)^2.
  EXPECT_NEAR(CountColour(image, colours::kRed), 3.14159 * 9.5 * 9.5, 12.0);
}

TEST(OverlayTest, PolygonFillMatchesAxisAlignedRectangleExactly) {
  RgbImage image(20, 20);
  Fill(image, kGrey);
  const std::vector<Eigen::Vector2d> rect = {{2.0, 3.0}, {12.0, 3.0}, {12.0, 8.0}, {2.0, 8.0}};
  FillPolygonPx(image, rect, colours::kBlue);
  EXPECT_EQ(CountColour(image, colours::kBlue), 10 * 5);
  EXPECT_EQ(PixelAt(image, 2, 3), colours::kBlue);
  EXPECT_EQ(PixelAt(image, 11, 7), colours::kBlue);
  EXPECT_EQ(PixelAt(image, 12, 7), kGrey);
  EXPECT_EQ(PixelAt(image, 2, 8), kGrey);
}

TEST(OverlayTest, LegendBoxSitsInItsCornerWithSwatches) {
  RgbImage image(300, 200);
  Fill(image, kGrey);
  const std::vector<PathOverlay> paths = {{"ground truth", {}, colours::kBlack, 2.0},
                                          {"", {}, colours::kGreen, 2.0},
                                          {"encoders", {}, colours::kRed, 2.0}};
  const std::vector<LegendEntry> entries = LegendFor(paths);
  ASSERT_EQ(entries.size(), 2u);
  const PixelRect box = DrawLegend(image, entries, Corner::kTopRight, 2, 8);
  EXPECT_EQ(box.x1, 300 - 8);
  EXPECT_EQ(box.y0, 8);
  EXPECT_GT(box.x1 - box.x0, TextWidthPx("ground truth", 2));
  EXPECT_EQ(CountColour(image, colours::kRed), TextHeightPx(2) * TextHeightPx(2));
  EXPECT_EQ(PixelAt(image, 4, 100), kGrey);  // outside the box untouched
}

TEST(BitmapFontTest, GlyphsHaveTheExpectedInk) {
  RgbImage image(40, 10);
  Fill(image, colours::kWhite);
  DrawText(image, 1, 1, "I-", colours::kBlack);
  // 'I' is a vertical bar in column 2 plus serifs in columns 1 and 3 of rows 0 and 6.
  for (int row = 0; row < 7; ++row) EXPECT_EQ(PixelAt(image, 1 + 2, 1 + row), colours::kBlack);
  EXPECT_EQ(PixelAt(image, 1 + 1, 1 + 0), colours::kBlack);
  EXPECT_EQ(PixelAt(image, 1 + 0, 1 + 3), colours::kWhite);
  // '-' is row 3 across all five columns of the second glyph.
  for (int col = 0; col < 5; ++col) EXPECT_EQ(PixelAt(image, 7 + col, 1 + 3), colours::kBlack);
  EXPECT_EQ(PixelAt(image, 7 + 2, 1 + 2), colours::kWhite);
  EXPECT_EQ(TextWidthPx("I-"), 11);
}

}  // namespace
}  // namespace plywood::render
