#include "render/snapshot.h"

#include <atomic>
#include <iostream>
#include <stdexcept>
#include <string>

#include "render/geom_footprint.h"
#include "render/offscreen_context.h"
#include "render/scale_bar.h"

namespace plywood::render {
namespace {

void WarnSoftwareFallbackOnce(const std::string& reason) {
  static std::atomic<bool> warned{false};
  if (!warned.exchange(true)) {
    std::cerr << "plywood: offscreen OpenGL rendering unavailable (" << reason
              << "); snapshots are drawn in software\n";
  }
}

}  // namespace

void SnapshotOptions::Validate() const {
  try {
    view.Validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("view.") + e.what());
  }
  if (legend_text_scale < 1 || legend_text_scale > 8) {
    throw std::invalid_argument("legend_text_scale: must be in [1, 8], got " +
                                std::to_string(legend_text_scale));
  }
}

WorldBounds SnapshotBounds(const mjModel* m, const std::vector<PathOverlay>& paths,
                           const SnapshotOptions& options) {
  WorldBounds bounds = StaticGeometryExtent(m).bounds;
  if (options.frame_paths) {
    for (const PathOverlay& path : paths) {
      for (const Eigen::Vector2d& p : path.points_W) {
        if (p.allFinite()) bounds.Extend(p);
      }
    }
  }
  return bounds;
}

Snapshot SoftwareSnapshot(const mjModel* m, const mjData* d, const WorldBounds& bounds,
                          const SnapshotOptions& options, const std::string& why) {
  if (options.use_opengl) WarnSoftwareFallbackOnce(why);
  return {RenderTopDownSoftware(m, d, bounds, options.view), SnapshotBackend::kSoftware};
}

std::string WhyNoOpenGl(const SnapshotOptions& options) {
  if (!options.use_opengl) return "";
  if (!OffscreenRenderingAvailable()) {
    return kHasOffscreenRendering ? "no OSMesa context" : "built without OSMesa";
  }
  return "";
}

void DrawSnapshotOverlays(Snapshot* snapshot, const std::vector<PathOverlay>& paths,
                          const SnapshotOptions& options) {
  if (options.scale_bar) {
    DrawScaleBarAndAxes(snapshot->picture.image, snapshot->picture.world_to_pixel);
  }
  DrawPaths(snapshot->picture.image, snapshot->picture.world_to_pixel, paths);
  if (options.legend) {
    DrawLegend(snapshot->picture.image, LegendFor(paths), options.legend_corner,
               options.legend_text_scale);
  }
}

Snapshot RenderSnapshot(const mjModel* m, mjData* d, const std::vector<PathOverlay>& paths,
                        const SnapshotOptions& options) {
  options.Validate();
  const WorldBounds bounds = SnapshotBounds(m, paths, options);
  Snapshot snapshot;
  bool drawn = false;
  std::string why;
  if (options.use_opengl) {
    // The renderer's own context is the test: an OffscreenRenderingAvailable() probe first would
    // make and destroy another (~75M instructions). Without any context, the probe's reason.
    try {
      TopDownRenderer renderer(m, bounds, options.view);
      snapshot.picture = renderer.Render(d);
      snapshot.backend = SnapshotBackend::kOpenGl;
      drawn = true;
    } catch (const std::runtime_error& e) {
      why = WhyNoOpenGl(options);
      if (why.empty()) why = e.what();
    }
  }
  if (!drawn) snapshot = SoftwareSnapshot(m, d, bounds, options, why);
  DrawSnapshotOverlays(&snapshot, paths, options);
  return snapshot;
}

SnapshotBackend WriteSnapshot(const mjModel* m, mjData* d, const std::vector<PathOverlay>& paths,
                              const std::filesystem::path& path, const SnapshotOptions& options) {
  Snapshot snapshot = RenderSnapshot(m, d, paths, options);
  WritePng(snapshot.picture.image, path);
  return snapshot.backend;
}

}  // namespace plywood::render
