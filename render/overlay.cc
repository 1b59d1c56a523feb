#include "render/overlay.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "render/bitmap_font.h"

namespace plywood::render {
namespace {

// Fraction of a pixel painted when its centre is `distance_px` from a shape's centre line of
// half-width `half_width_px`: a one-pixel linear ramp centred on the edge.
double Coverage(double distance_px, double half_width_px) {
  return std::clamp(half_width_px + 0.5 - distance_px, 0.0, 1.0);
}

double DistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length_sq = ab.squaredNorm();
  if (std::isinf(length_sq)) {
    // A segment longer than 1e154 px (its squared length overflows): along its unit direction.
    const double length = ab.stableNorm();
    const Eigen::Vector2d u = ab / length;
    return (p - (a + std::clamp((p - a).dot(u), 0.0, length) * u)).norm();
  }
  const double t = length_sq > 0.0 ? std::clamp((p - a).dot(ab) / length_sq, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// The whole pixels whose centres lie within `reach_px` of the box [lo, hi], clipped to the image.
struct PixelBox {
  int x0, y0, x1, y1;
};

// A whole-pixel coordinate clamped to [lo, hi] as a double first: a shape far off the image (an
// estimate that ran away, 1e12 px) has coordinates no int holds, and the cast alone is undefined
// (on x86 it gave INT_MIN, and the visible part of a segment to there was not drawn). NaN gives lo.
int ClampedPixel(double whole, int lo, int hi) {
  if (!(whole > lo)) return lo;  // NaN too
  return whole >= hi ? hi : static_cast<int>(whole);
}

PixelBox BoxNear(int width, int height, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                 double reach_px) {
  return {ClampedPixel(std::floor(lo.x() - reach_px), 0, width),
          ClampedPixel(std::floor(lo.y() - reach_px), 0, height),
          ClampedPixel(std::ceil(hi.x() + reach_px), -1, width - 1),
          ClampedPixel(std::ceil(hi.y() + reach_px), -1, height - 1)};
}

// Calls visit(x, y), row by row, for the pixels of the box within `reach_px` of [a, b] whose
// centres may lie within `reach_px` of the segment's line (a pixel to spare each side). A long
// diagonal's box holds ~length^2 pixels, this strip ~length; the pixels left out lie farther than
// `reach_px` from the segment.
template <typename V>
void ForSegmentStrip(int width, int height, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                     double reach_px, V visit) {
  const PixelBox box = BoxNear(width, height, a.cwiseMin(b), a.cwiseMax(b), reach_px);
  const Eigen::Vector2d d = b - a;
  // |d.y (x - a.x) - d.x (y - a.y)| <= reach |d| on the strip: in row y, x within half_span of the
  // line's x there. A segment less than a pixel from horizontal spans its (short) box, which also
  // keeps half_span and the line's x far from overflow and cancellation.
  const bool by_strip = std::abs(d.y()) >= 1.0;
  const double half_span = by_strip ? reach_px * d.norm() / std::abs(d.y()) : 0.0;
  for (int y = box.y0; y <= box.y1; ++y) {
    int x0 = box.x0, x1 = box.x1;
    if (by_strip) {
      const double line_x = a.x() + d.x() * (y + 0.5 - a.y()) / d.y();
      const double lo = std::floor(line_x - half_span - 0.5) - 1.0;
      const double hi = std::ceil(line_x + half_span - 0.5) + 1.0;
      if (lo > x0) x0 = lo > x1 ? x1 + 1 : static_cast<int>(lo);
      if (hi < x1) x1 = hi < x0 ? x0 - 1 : static_cast<int>(hi);
    }
    for (int x = x0; x <= x1; ++x) visit(x, y);
  }
}

// Pieces of a segment reaching beyond this many px are cut away unless near the image: there a
// coordinate's rounding is over 2^-22 px, and beyond 2^52 px over a pixel, so the distance from a
// pixel to the whole segment (its nearest point a + t (b - a) found through those coordinates)
// says little about where the line crosses the image: one from -1e16 to 1e16 px painted nothing.
constexpr double kFarPx = 1 << 30;

// Calls visit(a', b') for pieces of [a, b] that together hold every point within `reach_px` of
// the image [0, width] x [0, height], each within kFarPx: the segment is halved until its pieces
// are that near, those whose box lies beyond `reach_px` of the image dropped. A midpoint
// 0.5 a + 0.5 b is exact to the ulps of its own size, so a piece by the image is exact to its
// own, not to those of the far ends. `reach_px` must be well below kFarPx, or pieces near the
// image would never be that near.
template <typename V>
void ForPiecesNearImage(int width, int height, double reach_px, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b, V visit) {
  if (std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff()) <= kFarPx) {
    visit(a, b);
    return;
  }
  const Eigen::Vector2d lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  if (hi.x() < -reach_px || hi.y() < -reach_px || lo.x() > width + reach_px ||
      lo.y() > height + reach_px) {
    return;
  }
  const Eigen::Vector2d middle = 0.5 * a + 0.5 * b;
  if (middle == a || middle == b) {  // no shorter halves (ends an ulp apart): the piece as it is
    visit(a, b);
    return;
  }
  ForPiecesNearImage(width, height, reach_px, a, middle, visit);
  ForPiecesNearImage(width, height, reach_px, middle, b, visit);
}

// Per-pixel coverage of one shape, so overlapping pieces of it blend once. The buffer covers only
// the shape's pixel box (every pixel within `reach_px` of [lo, hi], clipped to the image): drawing
// costs what the shape covers, not the whole image.
class CoverageMask {
 public:
  CoverageMask(const RgbImage& image, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
               double reach_px)
      : width_(image.width), height_(image.height) {
    const PixelBox box = BoxNear(lo, hi, reach_px);
    x0_ = box.x0;
    y0_ = box.y0;
    stride_ = std::max(0, box.x1 - box.x0 + 1);
    const int rows = std::max(0, box.y1 - box.y0 + 1);
    coverage_.assign(static_cast<std::size_t>(stride_) * rows, 0.0f);
  }

  // Visits the pixels whose centres lie within `reach_px` of the box [lo, hi], which must lie
  // inside the box the mask was made for.
  template <typename F>
  void ForPixelsNear(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double reach_px, F f) {
    const PixelBox box = BoxNear(lo, hi, reach_px);
    for (int y = box.y0; y <= box.y1; ++y) {
      for (int x = box.x0; x <= box.x1; ++x) {
        Cover(x, y, f(Eigen::Vector2d(x + 0.5, y + 0.5)));
      }
    }
  }

  // As ForPixelsNear for the segment [a, b], over its strip (ForSegmentStrip) instead of its box.
  template <typename F>
  void ForPixelsNearSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double reach_px,
                            F f) {
    ForSegmentStrip(width_, height_, a, b, reach_px,
                    [&](int x, int y) { Cover(x, y, f(Eigen::Vector2d(x + 0.5, y + 0.5))); });
  }

  void BlendInto(RgbImage& image, Rgb colour) const {
    for (int y = touched_y0_; y <= touched_y1_; ++y) {
      for (int x = touched_x0_; x <= touched_x1_; ++x) {
        const float c = coverage_[static_cast<std::size_t>(y - y0_) * stride_ + (x - x0_)];
        if (c > 0.0f) BlendPixel(image, x, y, colour, c);
      }
    }
  }

 private:
  // Pixel (x, y) covered by c (the largest of the shape's pieces counts).
  void Cover(int x, int y, double c) {
    if (c <= 0.0) return;
    float& cell = coverage_[static_cast<std::size_t>(y - y0_) * stride_ + (x - x0_)];
    cell = std::max(cell, static_cast<float>(c));
    touched_x0_ = std::min(touched_x0_, x);
    touched_y0_ = std::min(touched_y0_, y);
    touched_x1_ = std::max(touched_x1_, x);
    touched_y1_ = std::max(touched_y1_, y);
  }

  PixelBox BoxNear(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double reach_px) const {
    return render::BoxNear(width_, height_, lo, hi, reach_px);
  }

  int width_, height_;
  int x0_ = 0, y0_ = 0, stride_ = 0;
  std::vector<float> coverage_;
  int touched_x0_ = 1 << 30, touched_y0_ = 1 << 30, touched_x1_ = -1, touched_y1_ = -1;
};

std::vector<Eigen::Vector2d> ToPixels(const WorldToPixel& map,
                                      std::span<const Eigen::Vector2d> points_W) {
  std::vector<Eigen::Vector2d> points_px;
  points_px.reserve(points_W.size());
  for (const Eigen::Vector2d& p : points_W) points_px.push_back(map.ToPixel(p));
  return points_px;
}

}  // namespace

void DrawPolylinePx(RgbImage& image, std::span<const Eigen::Vector2d> points_px, Rgb colour,
                    double width_px) {
  if (points_px.empty() || image.width <= 0 || !(width_px > 0.0)) return;
  const double half = 0.5 * width_px;
  // The pixel box of every drawable segment, so the mask is sized before drawing.
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (const Eigen::Vector2d& p : points_px) {
    if (!p.allFinite()) continue;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (!lo.allFinite()) return;
  const std::size_t n_segments = points_px.size() == 1 ? 1 : points_px.size() - 1;
  // A polyline reaching beyond kFarPx is drawn by its pieces near the image, which a mask blends
  // once (a line wider than 2^20 px covers the image wherever it is, and is drawn whole; no image
  // is that large).
  const bool far = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff()) > kFarPx &&
                   half + 1.0 < (1 << 20) && std::max(image.width, image.height) < (1 << 20);
  // Coverage is 0 from half + 0.5 px off the centre line on: the segments' strips reach that far.
  if (n_segments == 1 && !far) {
    // One segment covers each pixel once, so it blends straight into the image (as the mask
    // would: its coverage rounded to float, nothing where that is 0) without a buffer its box's
    // size: a replay draws ~10^5 of them.
    const Eigen::Vector2d& a = points_px.front();
    const Eigen::Vector2d& b = points_px.back();
    if (!a.allFinite() || !b.allFinite()) return;
    ForSegmentStrip(image.width, image.height, a, b, half + 0.5, [&](int x, int y) {
      const float c = static_cast<float>(
          Coverage(DistanceToSegment(Eigen::Vector2d(x + 0.5, y + 0.5), a, b), half));
      if (c > 0.0f) BlendPixel(image, x, y, colour, c);
    });
    return;
  }
  CoverageMask mask(image, lo, hi, half + 1.0);
  for (std::size_t i = 0; i < n_segments; ++i) {
    const Eigen::Vector2d& a = points_px[i];
    const Eigen::Vector2d& b = points_px[i + 1];
    if (!a.allFinite() || !b.allFinite()) continue;
    const auto cover = [&](const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
      mask.ForPixelsNearSegment(from, to, half + 0.5, [&](const Eigen::Vector2d& p) {
        return Coverage(DistanceToSegment(p, from, to), half);
      });
    };
    if (far) {
      ForPiecesNearImage(image.width, image.height, half + 1.0, a, b, cover);
    } else {
      cover(a, b);
    }
  }
  mask.BlendInto(image, colour);
}

void FillCirclePx(RgbImage& image, const Eigen::Vector2d& centre_px, double radius_px, Rgb colour) {
  if (image.width <= 0 || !(radius_px > 0.0) || !centre_px.allFinite()) return;
  CoverageMask mask(image, centre_px, centre_px, radius_px + 1.0);
  mask.ForPixelsNear(centre_px, centre_px, radius_px + 1.0, [&](const Eigen::Vector2d& p) {
    return Coverage((p - centre_px).norm(), radius_px);
  });
  mask.BlendInto(image, colour);
}

void DrawCirclePx(RgbImage& image, const Eigen::Vector2d& centre_px, double radius_px, Rgb colour,
                  double width_px) {
  if (image.width <= 0 || !(radius_px > 0.0) || !(width_px > 0.0) || !centre_px.allFinite()) {
    return;
  }
  const double half = 0.5 * width_px;
  CoverageMask mask(image, centre_px, centre_px, radius_px + half + 1.0);
  mask.ForPixelsNear(centre_px, centre_px, radius_px + half + 1.0, [&](const Eigen::Vector2d& p) {
    return Coverage(std::abs((p - centre_px).norm() - radius_px), half);
  });
  mask.BlendInto(image, colour);
}

void FillPolygonPx(RgbImage& image, std::span<const Eigen::Vector2d> vertices_px, Rgb colour) {
  if (vertices_px.size() < 3) return;
  double y_lo = vertices_px[0].y(), y_hi = y_lo;
  for (const Eigen::Vector2d& v : vertices_px) {
    y_lo = std::min(y_lo, v.y());
    y_hi = std::max(y_hi, v.y());
  }
  const int row0 = ClampedPixel(std::floor(y_lo), 0, image.height);
  const int row1 = ClampedPixel(std::ceil(y_hi), -1, image.height - 1);
  std::vector<double> crossings;
  for (int row = row0; row <= row1; ++row) {
    const double y = row + 0.5;
    crossings.clear();
    for (std::size_t i = 0; i < vertices_px.size(); ++i) {
      const Eigen::Vector2d& a = vertices_px[i];
      const Eigen::Vector2d& b = vertices_px[(i + 1) % vertices_px.size()];
      // Half-open in y so a vertex on the scan line counts once.
      if ((a.y() <= y) != (b.y() <= y)) {
        crossings.push_back(a.x() + (y - a.y()) / (b.y() - a.y()) * (b.x() - a.x()));
      }
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
      // Pixels whose centre x + 0.5 lies in [crossings[k], crossings[k + 1]).
      const int x0 = ClampedPixel(std::ceil(crossings[k] - 0.5), 0, image.width);
      const int x1 = ClampedPixel(std::ceil(crossings[k + 1] - 0.5), 0, image.width);
      for (int x = x0; x < x1; ++x) BlendPixel(image, x, row, colour);
    }
  }
}

void FillRectPx(RgbImage& image, int x0, int y0, int x1, int y1, Rgb colour, double alpha) {
  for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y) {
    for (int x = std::max(0, x0); x < std::min(image.width, x1); ++x) {
      BlendPixel(image, x, y, colour, alpha);
    }
  }
}

void DrawPolyline(RgbImage& image, const WorldToPixel& map,
                  std::span<const Eigen::Vector2d> points_W, Rgb colour, double width_px) {
  const std::vector<Eigen::Vector2d> points_px = ToPixels(map, points_W);
  DrawPolylinePx(image, points_px, colour, width_px);
}

void DrawSegment(RgbImage& image, const WorldToPixel& map, const Eigen::Vector2d& a_W,
                 const Eigen::Vector2d& b_W, Rgb colour, double width_px) {
  const Eigen::Vector2d points_px[] = {map.ToPixel(a_W), map.ToPixel(b_W)};
  DrawPolylinePx(image, points_px, colour, width_px);
}

void DrawPoint(RgbImage& image, const WorldToPixel& map, const Eigen::Vector2d& p_W, Rgb colour,
               double radius_px) {
  FillCirclePx(image, map.ToPixel(p_W), radius_px, colour);
}

void DrawCircle(RgbImage& image, const WorldToPixel& map, const Eigen::Vector2d& centre_W,
                double radius_m, Rgb colour, double width_px) {
  DrawCirclePx(image, map.ToPixel(centre_W), radius_m * map.pixels_per_m, colour, width_px);
}

void DrawPoseMarker(RgbImage& image, const WorldToPixel& map, const Eigen::Vector2d& p_W,
                    double theta_rad, Rgb colour, double length_px) {
  // Image v points down, so a world heading theta is (cos, -sin) in pixels.
  const Eigen::Vector2d forward(std::cos(theta_rad), -std::sin(theta_rad));
  const Eigen::Vector2d left(-forward.y(), forward.x());
  const Eigen::Vector2d c = map.ToPixel(p_W);
  const Eigen::Vector2d triangle[] = {c + 0.6 * length_px * forward,
                                      c - 0.4 * length_px * forward + 0.3 * length_px * left,
                                      c - 0.4 * length_px * forward - 0.3 * length_px * left};
  FillPolygonPx(image, triangle, colour);
}

void DrawPaths(RgbImage& image, const WorldToPixel& map, std::span<const PathOverlay> paths) {
  for (const PathOverlay& path : paths) {
    if (path.points_W.empty()) continue;
    DrawPolyline(image, map, path.points_W, path.colour, path.width_px);
    DrawPoint(image, map, path.points_W.front(), path.colour, path.width_px + 2.0);
    DrawCircle(image, map, path.points_W.back(), (path.width_px + 3.0) / map.pixels_per_m,
               path.colour, 1.5);
  }
}

PixelRect DrawLegend(RgbImage& image, std::span<const LegendEntry> entries, Corner corner,
                     int text_scale, int margin_px) {
  if (entries.empty()) return {};
  const int pad = 3 * text_scale;
  const int row_h = TextHeightPx(text_scale) + pad;
  const int swatch = TextHeightPx(text_scale);
  int text_w = 0;
  for (const LegendEntry& e : entries) text_w = std::max(text_w, TextWidthPx(e.label, text_scale));
  const int box_w = pad + swatch + pad + text_w + pad;
  const int box_h = pad + static_cast<int>(entries.size()) * row_h;
  const bool left = corner == Corner::kTopLeft || corner == Corner::kBottomLeft;
  const bool top = corner == Corner::kTopLeft || corner == Corner::kTopRight;
  PixelRect box;
  box.x0 = left ? margin_px : image.width - margin_px - box_w;
  box.y0 = top ? margin_px : image.height - margin_px - box_h;
  box.x1 = box.x0 + box_w;
  box.y1 = box.y0 + box_h;
  FillRectPx(image, box.x0, box.y0, box.x1, box.y1, colours::kWhite, 0.85);
  FillRectPx(image, box.x0, box.y0, box.x1, box.y0 + 1, colours::kBlack);
  FillRectPx(image, box.x0, box.y1 - 1, box.x1, box.y1, colours::kBlack);
  FillRectPx(image, box.x0, box.y0, box.x0 + 1, box.y1, colours::kBlack);
  FillRectPx(image, box.x1 - 1, box.y0, box.x1, box.y1, colours::kBlack);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const int y = box.y0 + pad + static_cast<int>(i) * row_h;
    FillRectPx(image, box.x0 + pad, y, box.x0 + pad + swatch, y + swatch, entries[i].colour);
    DrawText(image, box.x0 + 2 * pad + swatch, y, entries[i].label, colours::kBlack, text_scale);
  }
  return box;
}

std::vector<LegendEntry> LegendFor(std::span<const PathOverlay> paths) {
  std::vector<LegendEntry> entries;
  for (const PathOverlay& path : paths) {
    if (!path.label.empty()) entries.push_back({path.label, path.colour});
  }
  return entries;
}

}  // namespace plywood::render
