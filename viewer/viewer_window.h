#pragma once

#include <mujoco/mujoco.h>

#include <functional>
#include <memory>
#include <string>

#include "render/png_image.h"
#include "render/world_to_pixel.h"
#include "viewer/overlay_primitives.h"

namespace plywood::viewer {

struct WindowOptions {
  int width_px = 1280;  // in [64, 8192]
  int height_px = 800;  // in [64, 8192]
  std::string title = "plywood";
  bool panel = true;  // the Dear ImGui panel (when the build has Dear ImGui)

  // @throws std::invalid_argument whose message starts with the offending field's name.
  void Validate() const;
};

enum class CameraPreset {
  kTopDown,  // straight down on the whole world, world +x right, +y up (an exact floor map)
  kFollow,   // orbits with the robot's base body
  kFree,     // wherever the mouse left it
};

// A GLFW window with MuJoCo's renderer (mjv / mjr, legacy OpenGL) on its context: camera presets,
// mouse orbit / pan / zoom, text blocks, an optional Dear ImGui panel, and screenshots. Keys go to
// the handler given with SetKeyHandler; HandleKey is the same entry point for tests.
// MuJoCo 2.2.2 looks its GL functions up once per process and prefers OSMesa once libOSMesa is
// loaded: after an offscreen snapshot (render/offscreen_context.h) the window draws nothing, so
// the viewer draws everything before a run's pictures are written.
class ViewerWindow {
 public:
  using KeyHandler = std::function<void(int key, int action, int mods)>;

  // Copies `m` (the copy sizes the scene and carries the viewer's lighting).
  // @throws std::runtime_error when GLFW cannot open a window (no display) or GL fails.
  ViewerWindow(const mjModel* m, const WindowOptions& options);
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow&) = delete;
  ViewerWindow& operator=(const ViewerWindow&) = delete;

  void SetKeyHandler(KeyHandler handler) { key_handler_ = std::move(handler); }
  void HandleKey(int key, int action, int mods);
  void PollEvents();
  // The close button was pressed, or the window is Gone().
  bool CloseRequested() const;
  // The X connection broke or another client destroyed the window (viewer/x_connection_loss.h):
  // nothing may be drawn any more.
  bool Gone() const;
  void SetTitle(const std::string& title);

  void SetPreset(CameraPreset preset, int follow_body_id = 0);
  CameraPreset preset() const { return preset_; }

  // Builds the frame's 3D scene from `d`; the caller may add geoms to the returned scene (up to its
  // maxgeom) and lines to overlay_primitives() before Finish.
  mjvScene& BeginFrame(mjData* d);
  // Lines drawn over the scene at Finish, depth-tested against it, without lighting; cleared by
  // BeginFrame.
  OverlayPrimitives& overlay_primitives() { return overlay_primitives_; }
  // Renders the scene, then `top_left` and `bottom_right` text (tab-separated "title\tvalue" lines,
  // empty: none), then the panel drawn by `panel` (Dear ImGui calls; ignored without Dear ImGui),
  // and shows the frame.
  void Finish(const std::string& top_left, const std::string& bottom_right,
              const std::function<void()>& panel = {});

  // While on, every Finish keeps a copy of the frame it shows (for screenshots and video).
  void SetCapture(bool on) { capture_ = on; }
  // The last frame finished while capture was on (empty before).
  const render::RgbImage& Screenshot() const { return captured_; }
  // Floor coordinates to screenshot pixels; exact in the top-down preset only.
  render::WorldToPixel TopDownMapping() const;
  int framebuffer_width() const;
  int framebuffer_height() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  KeyHandler key_handler_;
  OverlayPrimitives overlay_primitives_;
  CameraPreset preset_ = CameraPreset::kTopDown;
  bool capture_ = false;
  render::RgbImage captured_;
};

}  // namespace plywood::viewer
