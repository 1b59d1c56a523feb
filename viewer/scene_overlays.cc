#include "viewer/scene_overlays.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/scale_bar.h"
#include "viewer/polyline_thinning.h"

namespace plywood::viewer {
namespace {

// Sends overlay lines to the batch and labels to the scene (until the scene is full).
class GeomSink {
 public:
  GeomSink(mjvScene& scene, OverlayPrimitives& lines) : scene_(scene), lines_(lines) {}

  void Line(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const float rgba[4],
            double width_px) {
    lines_.Add(a, b, rgba, width_px);
  }
  void Rectangle(const Eigen::Vector2d& min, const Eigen::Vector2d& max, double z,
                 const float rgba[4]) {
    lines_.AddRectangle(min, max, z, rgba);
  }
  void Label(const Eigen::Vector3d& p, const char* text, const float rgba[4]) {
    if (scene_.ngeom >= scene_.maxgeom) return;
    mjvGeom* g = &scene_.geoms[scene_.ngeom++];
    const mjtNum size[3] = {0.05, 0.05, 0.05};
    const mjtNum pos[3] = {p.x(), p.y(), p.z()};
    mjv_initGeom(g, mjGEOM_LABEL, size, pos, nullptr, rgba);
    g->category = mjCAT_DECOR;
    g->objtype = mjOBJ_UNKNOWN;
    g->objid = -1;
    std::snprintf(g->label, sizeof(g->label), "%s", text);
  }

 private:
  mjvScene& scene_;
  OverlayPrimitives& lines_;
};

Eigen::Vector3d At(const Eigen::Vector2d& p, double z) { return {p.x(), p.y(), z}; }

Eigen::Vector2d Along(const msgs::Pose2D& X, double angle_rad, double range_m) {
  const double a = X.theta_rad + angle_rad;
  return {X.x_m + range_m * std::cos(a), X.y_m + range_m * std::sin(a)};
}

const float* KindColour(RingReadingKind kind) {
  switch (kind) {
    case RingReadingKind::kEcho:
      return overlay_colours::kEcho;
    case RingReadingKind::kSpecularMiss:
      return overlay_colours::kSpecularMiss;
    case RingReadingKind::kMultipath:
      return overlay_colours::kMultipath;
    case RingReadingKind::kNothing:
      return overlay_colours::kNothing;
  }
  return overlay_colours::kNothing;
}

// A cone as its two edges and an arc at the reading's range (range_max without an echo).
void AddRing(GeomSink& sink, const RingView& view, const float* single_colour) {
  for (std::size_t i = 0; i < view.ring.readings.size(); ++i) {
    const msgs::RangeReading& r = view.ring.readings[i];
    const msgs::Pose2D X_WS = view.X_WR * r.X_RS;
    const float* colour = single_colour ? single_colour : KindColour(view.kinds[i]);
    const double range = r.echo ? r.range_m : view.ring.range_max_m;
    const Eigen::Vector2d origin(X_WS.x_m, X_WS.y_m);
    if (view.half_angle_rad <= 0.0) {
      if (r.echo)
        sink.Line(At(origin, view.height_m), At(Along(X_WS, 0, range), view.height_m), colour, 2.0);
      continue;
    }
    constexpr int kArcSegments = 6;
    Eigen::Vector2d previous = Along(X_WS, -view.half_angle_rad, range);
    sink.Line(At(origin, view.height_m), At(previous, view.height_m), colour, 1.0);
    for (int k = 1; k <= kArcSegments; ++k) {
      const double a = -view.half_angle_rad + 2.0 * view.half_angle_rad * k / kArcSegments;
      const Eigen::Vector2d p = Along(X_WS, a, range);
      sink.Line(At(previous, view.height_m), At(p, view.height_m), colour, 2.0);
      previous = p;
    }
    sink.Line(At(origin, view.height_m), At(previous, view.height_m), colour, 1.0);
  }
}

}  // namespace

void AddOverlays(mjvScene& scene, OverlayPrimitives& lines, const FrameContent& content,
                 const ViewControls& controls, const render::WorldBounds& world) {
  GeomSink sink(scene, lines);
  constexpr double kFloorZ = 0.01;  // just above the floor, under everything else
  if (controls.overlay(Overlay::kScaleBar)) {
    // Axes at the world origin and a scale bar along the bottom-left corner of the world.
    const double length = render::NiceScaleLengthM(std::max(world.width_m(), world.height_m()));
    const float red[4] = {0.9f, 0.1f, 0.1f, 1.0f}, green[4] = {0.1f, 0.7f, 0.1f, 1.0f};
    sink.Line({0, 0, kFloorZ}, {length, 0, kFloorZ}, red, 3.0);
    sink.Line({0, 0, kFloorZ}, {0, length, kFloorZ}, green, 3.0);
    sink.Label({length, 0, kFloorZ}, "x", red);
    sink.Label({0, length, kFloorZ}, "y", green);
    const Eigen::Vector2d start(world.x_min_m + 0.2, world.y_min_m + 0.2);
    sink.Line(At(start, kFloorZ), At(start + Eigen::Vector2d(length, 0), kFloorZ),
              overlay_colours::kScaleBar, 4.0);
    char text[32];
    std::snprintf(text, sizeof(text), "%g m", length);
    sink.Label(At(start + Eigen::Vector2d(0, 0.15), kFloorZ), text, overlay_colours::kScaleBar);
  }
  if (controls.overlay(Overlay::kPaths)) {
    constexpr double kPathToleranceM = 0.005;  // below a pixel at any useful zoom
    for (const PathView& path : content.paths) {
      const std::vector<Eigen::Vector2d> drawn = ThinPolyline(path.points_W, kPathToleranceM);
      for (std::size_t i = 1; i < drawn.size(); ++i) {
        sink.Line(At(drawn[i - 1], kFloorZ + 0.01), At(drawn[i], kFloorZ + 0.01), path.rgba, 2.5);
      }
    }
  }
  if (controls.overlay(Overlay::kLaser) && content.laser) {
    const LaserView& l = *content.laser;
    const Eigen::Vector2d origin(l.X_WS.x_m, l.X_WS.y_m);
    for (std::size_t i = 0; i < l.ranges_m.size(); ++i) {
      if (!(l.ranges_m[i] < l.range_max_m)) continue;
      sink.Line(At(origin, l.height_m),
                At(Along(l.X_WS, l.angles_rad[i], l.ranges_m[i]), l.height_m),
                overlay_colours::kLaserBeam, 1.0);
    }
  }
  if (controls.overlay(Overlay::kSonar) && content.sonar) AddRing(sink, *content.sonar, nullptr);
  if (controls.overlay(Overlay::kIr) && content.ir) {
    AddRing(sink, *content.ir, overlay_colours::kIr);
  }
  if (controls.overlay(Overlay::kMap) && content.map) {
    constexpr double kMapZ = 0.02;
    for (const MapView::Box& box : content.map->partitions) {
      const Eigen::Vector2d corners[] = {
          box.min_W, {box.max_W.x(), box.min_W.y()}, box.max_W, {box.min_W.x(), box.max_W.y()}};
      const float* colour =
          box.free ? overlay_colours::kFreePartition : overlay_colours::kObstaclePartition;
      for (int k = 0; k < 4; ++k) {
        sink.Line(At(corners[k], kMapZ), At(corners[(k + 1) % 4], kMapZ), colour, 1.5);
      }
    }
    for (const auto& [a, b] : content.map->graph_arcs) {
      sink.Line(At(a, kMapZ + 0.01), At(b, kMapZ + 0.01), overlay_colours::kGraphArc, 3.0);
    }
  }
  if (controls.overlay(Overlay::kGrid) && content.grid) {
    // Cells the grid has an opinion on; unknown ones (p near 0.5) let the floor show.
    const GridView& grid = *content.grid;
    const Eigen::Vector2d half(0.5 * grid.cell_m, 0.5 * grid.cell_m);
    for (int iy = 0; iy < grid.height; ++iy) {
      for (int ix = 0; ix < grid.width; ++ix) {
        const float p = grid.occupied_p[static_cast<std::size_t>(iy) * grid.width + ix];
        if (std::abs(p - 0.5f) < 0.1f) continue;
        const Eigen::Vector2d centre =
            grid.cell_00_centre_W + grid.cell_m * Eigen::Vector2d(ix, iy);
        sink.Rectangle(centre - half, centre + half, kFloorZ + 0.005,
                       p > 0.5f ? overlay_colours::kOccupiedCell : overlay_colours::kFreeCell);
      }
    }
  }
  if (controls.overlay(Overlay::kMap) && content.geometric_map) {
    constexpr double kMapZ = 0.03;
    for (const GeometricMapView::Segment& s : content.geometric_map->segments) {
      if (!s.pseudo) {
        sink.Line(At(s.a_W, kMapZ), At(s.b_W, kMapZ), overlay_colours::kRealSegment, 3.0);
        continue;
      }
      // Dashes of 10 cm every 20 cm, as geometric_map.png, counted by a whole number: a pseudo
      // segment 1e300 m long (a hand-edited geometric_map.json) looped for ever on `t += 0.2`,
      // and one of 1e8 m would take 5e8 dashes of memory (s63). Longer than any room a run maps,
      // it is drawn whole.
      const Eigen::Vector2d d = s.b_W - s.a_W;
      const double length = d.norm();
      constexpr double kDashPeriodM = 0.2;
      constexpr double kMaxDashes = 10000;  // 2 km
      if (!(length / kDashPeriodM <= kMaxDashes)) {
        sink.Line(At(s.a_W, kMapZ), At(s.b_W, kMapZ), overlay_colours::kPseudoSegment, 2.0);
        continue;
      }
      const int dashes = static_cast<int>(std::ceil(length / kDashPeriodM));
      for (int k = 0; k < dashes; ++k) {
        const double t = k * kDashPeriodM;
        sink.Line(At(s.a_W + d * (t / length), kMapZ),
                  At(s.a_W + d * (std::min(t + 0.1, length) / length), kMapZ),
                  overlay_colours::kPseudoSegment, 2.0);
      }
    }
    for (const auto& [a, b] : content.geometric_map->clusters) {
      const Eigen::Vector2d corners[] = {a, {b.x(), a.y()}, b, {a.x(), b.y()}};
      for (int k = 0; k < 4; ++k) {
        sink.Line(At(corners[k], kMapZ), At(corners[(k + 1) % 4], kMapZ), overlay_colours::kCluster,
                  2.0);
      }
    }
  }
  if (controls.overlay(Overlay::kLines)) {
    for (const SegmentView& s : content.lines) {
      sink.Line(At(s.a_W, 0.5), At(s.b_W, 0.5),
                s.matched ? overlay_colours::kMatchedLine : overlay_colours::kUnmatchedLine, 4.0);
    }
  }
}

}  // namespace plywood::viewer
