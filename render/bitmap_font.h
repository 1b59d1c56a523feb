#pragma once

#include <string_view>

#include "render/image_ops.h"

namespace plywood::render {

// A 5 x 7 pixel ASCII font (the classic HD44780-style LCD glyphs) for legends and labels, so
// snapshots need no font files. Each glyph advances 6 pixels; `scale` enlarges every font pixel to
// scale x scale image pixels. Characters outside 32..126 are drawn as '?'.
inline constexpr int kGlyphWidthPx = 5;
inline constexpr int kGlyphHeightPx = 7;
inline constexpr int kGlyphAdvancePx = 6;

// Size in image pixels of `text` drawn at `scale`.
int TextWidthPx(std::string_view text, int scale = 1);
inline int TextHeightPx(int scale = 1) { return kGlyphHeightPx * scale; }

// Draws `text` with its top-left corner at pixel (x, y); pixels outside the image are skipped.
void DrawText(RgbImage& image, int x, int y, std::string_view text, Rgb colour, int scale = 1);

}  // namespace plywood::render
