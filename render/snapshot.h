#pragma once

#include <mujoco/mujoco.h>

#include <filesystem>
#include <string>
#include <vector>

#include "render/overlay.h"
#include "render/top_down_renderer.h"

namespace plywood::render {

struct SnapshotOptions {
  TopDownOptions view;
  bool frame_paths = true;  // widen the framed bounds so every path point is in the picture
  bool legend = true;       // a legend box for the labelled paths
  Corner legend_corner = Corner::kTopRight;
  int legend_text_scale = 2;
  bool scale_bar = true;   // a scale bar (bottom left) and the world axes at the origin
  bool use_opengl = true;  // false: always draw in software (deterministic pixels)

  // @throws std::invalid_argument whose message starts with the offending field's name.
  void Validate() const;
};

enum class SnapshotBackend { kOpenGl, kSoftware };

struct Snapshot {
  TopDownImage picture;
  SnapshotBackend backend = SnapshotBackend::kSoftware;
};

// A top-down picture of the world in `d` framing the static geometry (and the paths), with `paths`
// drawn over it and a legend. Tries MuJoCo's OpenGL renderer offscreen; when that is unavailable
// or fails, draws the geoms' footprints in software with the same framing and says so on stderr
// (once per process). The returned WorldToPixel lets callers add further overlays.
// @throws std::invalid_argument on bad options.
Snapshot RenderSnapshot(const mjModel* m, mjData* d, const std::vector<PathOverlay>& paths,
                        const SnapshotOptions& options = {});

// RenderSnapshot's steps, for callers that keep their own renderer (AsyncSnapshotWriter), so the
// pictures cannot differ:
// - the floor rectangle framed: the static geometry, widened to the paths with frame_paths;
WorldBounds SnapshotBounds(const mjModel* m, const std::vector<PathOverlay>& paths,
                           const SnapshotOptions& options);
// - why OpenGL cannot draw it (empty: it can try, or options.use_opengl is false);
std::string WhyNoOpenGl(const SnapshotOptions& options);
// - the software picture; when options.use_opengl, says once per process on stderr why not GL;
Snapshot SoftwareSnapshot(const mjModel* m, const mjData* d, const WorldBounds& bounds,
                          const SnapshotOptions& options, const std::string& why);
// - the scale bar, the paths and their legend drawn over the picture.
void DrawSnapshotOverlays(Snapshot* snapshot, const std::vector<PathOverlay>& paths,
                          const SnapshotOptions& options);

// RenderSnapshot, then writes the PNG to `path`. Returns which renderer drew it.
// @throws std::invalid_argument on bad options, std::runtime_error naming `path` when writing
// fails.
SnapshotBackend WriteSnapshot(const mjModel* m, mjData* d, const std::vector<PathOverlay>& paths,
                              const std::filesystem::path& path,
                              const SnapshotOptions& options = {});

}  // namespace plywood::render
