#pragma once

#include "render/png_image.h"
#include "render/world_to_pixel.h"

namespace plywood::render {

// A length near a fifth of `span_m` that reads well on a scale bar: 1, 2 or 5 times a power of
// ten. @pre span_m > 0.
double NiceScaleLengthM(double span_m);

// A scale bar with its length in metres in the bottom-left corner, and the world axes (x red,
// y green, each one scale length from the origin) when the origin is in the picture.
void DrawScaleBarAndAxes(RgbImage& image, const WorldToPixel& map);

}  // namespace plywood::render
