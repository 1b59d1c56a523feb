#include "viewer/viewer_window.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/geom_footprint.h"
#include "render/image_ops.h"
#include "render/top_down_renderer.h"
#include "sim/world/mujoco_handles.h"
#include "sim/world/scene.h"
#include "viewer/display_probe.h"
#include "viewer/gl_driver_pin.h"
#include "viewer/x_connection_loss.h"

#if PLYWOOD_HAS_IMGUI
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl2.h>
#endif

namespace plywood::viewer {
namespace {

constexpr double kFloorGridM = 0.5;  // rendering grid of planes, see the constructor
constexpr int kSceneGeoms = 20000;   // the world, the robot and every overlay line

// Draws `overlays` with the projection and modelview mjr_render left for the scene's camera (its
// text labels are drawn with them too), as MuJoCo draws a line geom: unlit, depth-tested. Line
// widths are 1.5x the requested pixels, as wide as MuJoCo 2.2.2 drew the same lines as geoms in
// this window (compared on the README's screenshot), so the overlays look as they did.
void DrawOverlayPrimitives(const OverlayPrimitives& overlays, float context_line_width) {
  constexpr float kAsMujocoDrewThem = 1.5f;
  if (overlays.batches().empty()) return;
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnableClientState(GL_VERTEX_ARRAY);
  // Filled areas first, under the lines.
  for (const auto kind : {OverlayPrimitives::Kind::kQuads, OverlayPrimitives::Kind::kLines}) {
    for (const OverlayPrimitives::Batch& batch : overlays.batches()) {
      if (batch.kind != kind) continue;
      glColor4fv(batch.rgba.data());
      glVertexPointer(3, GL_FLOAT, 0, batch.xyz.data());
      const auto vertices = static_cast<GLsizei>(batch.xyz.size() / 3);
      if (kind == OverlayPrimitives::Kind::kQuads) {
        glDrawArrays(GL_QUADS, 0, vertices);
      } else {
        glLineWidth(kAsMujocoDrewThem * batch.width_px * context_line_width);
        glDrawArrays(GL_LINES, 0, vertices);
      }
    }
  }
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisable(GL_BLEND);
  glLineWidth(context_line_width);
  glEnable(GL_LIGHTING);
}

}  // namespace

void WindowOptions::Validate() const {
  const auto check = [](const char* field, int value) {
    if (value < 64 || value > 8192) {
      throw std::invalid_argument(std::string(field) + ": must be in [64, 8192], got " +
                                  std::to_string(value));
    }
  };
  check("width_px", width_px);
  check("height_px", height_px);
}

struct ViewerWindow::Impl {
  GLFWwindow* window = nullptr;
  sim::MjModelPtr model;
  mjvScene scene;
  mjrContext con;
  mjvOption option;
  mjvCamera camera;
  mjvGLCamera top_down_camera{};
  render::WorldToPixel top_down_map;
  render::WorldBounds world_bounds;
  double z_top_m = 0.0;
  bool imgui = false;
  // Mouse state for orbit / pan / zoom.
  bool left = false, right = false, middle = false;
  double last_x = 0.0, last_y = 0.0;
  ViewerWindow* owner = nullptr;

  Impl() {
    mjv_defaultScene(&scene);
    mjr_defaultContext(&con);
    mjv_defaultOption(&option);
    mjv_defaultCamera(&camera);
  }
};

ViewerWindow::ViewerWindow(const mjModel* m, const WindowOptions& options)
    : impl_(std::make_unique<Impl>()) {
  options.Validate();
  Impl& g = *impl_;
  g.owner = this;
  if (const std::optional<std::string> problem = StartGlfw())
    throw std::runtime_error("viewer: cannot start GLFW: " + *problem);
  InstallXConnectionLossHandler();
  glfwWindowHint(GLFW_SAMPLES, 0);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  g.window = glfwCreateWindow(options.width_px, options.height_px, options.title.c_str(), nullptr,
                              nullptr);
  if (g.window == nullptr) {
    glfwTerminate();
    throw std::runtime_error("viewer: cannot open a window: " + LastGlfwError());
  }
  glfwMakeContextCurrent(g.window);
  PinLoadedGlDrivers();  // loaded with the context; see gl_driver_pin.h for why it stays
  glfwSwapInterval(0);   // the run paces itself; vsync would cap "as fast as possible"
  glfwSetWindowUserPointer(g.window, this);
  WatchXWindow(g.window);

  g.model.reset(mj_copyModel(nullptr, m));
  mjModel* copy = g.model.get();
  for (int i = 0; i < 3; ++i) {
    copy->vis.headlight.ambient[i] = 0.3f;
    copy->vis.headlight.diffuse[i] = 0.5f;
    copy->vis.headlight.specular[i] = 0.0f;
  }
  copy->vis.headlight.active = 1;
  copy->vis.quality.shadowsize = 0;  // see TopDownRenderer: a shadow map costs more than it shows
  // Software GL (llvmpipe under Xvfb, the usual case on a lab server) spends most of a frame on
  // vertices: a plane is drawn as quads of its grid spacing (0.05 m in the shipped worlds: 75,000
  // quads for the office floor) and round geoms with 28 x 16 facets. Lighting is per vertex and
  // every shipped light is directional, so a 0.5 m floor grid shades the same; 16 x 8 facets
  // still look round at the robot's size.
  for (int i = 0; i < copy->ngeom; ++i) {
    if (copy->geom_type[i] == mjGEOM_PLANE) {
      copy->geom_size[3 * i + 2] = std::max<mjtNum>(copy->geom_size[3 * i + 2], kFloorGridM);
    }
  }
  copy->vis.quality.numslices = std::min(copy->vis.quality.numslices, 16);
  copy->vis.quality.numstacks = std::min(copy->vis.quality.numstacks, 8);
  mjv_makeScene(copy, &g.scene, kSceneGeoms);
  mjr_makeContext(copy, &g.con, mjFONTSCALE_150);
  mjr_setBuffer(mjFB_WINDOW, &g.con);
  // Bilinear instead of MuJoCo's trilinear (mipmapped) filtering: a third less per-pixel work in
  // software GL, and the floor's checker is drawn near one texel per pixel anyway.
  for (int i = 0; i < g.con.ntexture; ++i) {
    if (g.con.textureType[i] != mjTEXTURE_2D) continue;
    glBindTexture(GL_TEXTURE_2D, g.con.texture[i]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  g.scene.flags[mjRND_SKYBOX] = 0;
  g.scene.flags[mjRND_REFLECTION] = 0;
  for (int i = 0; i < mjNGROUP; ++i) g.option.sitegroup[i] = 0;  // sensor sites clutter the view
  g.option.geomgroup[sim::Scene::kRobotGeomGroup] = 1;           // hidden by MuJoCo's default

  const render::StaticExtent extent = render::StaticGeometryExtent(copy);
  g.world_bounds = extent.bounds.Padded(0.5);
  g.z_top_m = extent.z_max_m;

  glfwSetKeyCallback(g.window, [](GLFWwindow* w, int key, int, int action, int mods) {
    auto* self = static_cast<ViewerWindow*>(glfwGetWindowUserPointer(w));
#if PLYWOOD_HAS_IMGUI
    if (self->impl_->imgui && ImGui::GetIO().WantCaptureKeyboard) return;
#endif
    self->HandleKey(key, action, mods);
  });
  glfwSetMouseButtonCallback(g.window, [](GLFWwindow* w, int, int, int) {
    auto* self = static_cast<ViewerWindow*>(glfwGetWindowUserPointer(w));
    Impl& i = *self->impl_;
#if PLYWOOD_HAS_IMGUI
    if (i.imgui && ImGui::GetIO().WantCaptureMouse) return;
#endif
    i.left = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    i.right = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    i.middle = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
    glfwGetCursorPos(w, &i.last_x, &i.last_y);
  });
  glfwSetCursorPosCallback(g.window, [](GLFWwindow* w, double x, double y) {
    auto* self = static_cast<ViewerWindow*>(glfwGetWindowUserPointer(w));
    Impl& i = *self->impl_;
    if (!i.left && !i.right && !i.middle) return;
    const double dx = x - i.last_x, dy = y - i.last_y;
    i.last_x = x;
    i.last_y = y;
    int width = 1, height = 1;
    glfwGetWindowSize(w, &width, &height);
    const bool shift = glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                       glfwGetKey(w, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
    const mjtMouse action = i.right  ? (shift ? mjMOUSE_MOVE_H : mjMOUSE_MOVE_V)
                            : i.left ? (shift ? mjMOUSE_ROTATE_H : mjMOUSE_ROTATE_V)
                                     : mjMOUSE_ZOOM;
    // Dragging leaves the exact top-down projection for the free camera it approximates.
    if (self->preset_ == CameraPreset::kTopDown) self->preset_ = CameraPreset::kFree;
    mjv_moveCamera(i.model.get(), action, dx / height, dy / height, &i.scene, &i.camera);
  });
  glfwSetScrollCallback(g.window, [](GLFWwindow* w, double, double dy) {
    auto* self = static_cast<ViewerWindow*>(glfwGetWindowUserPointer(w));
    Impl& i = *self->impl_;
#if PLYWOOD_HAS_IMGUI
    if (i.imgui && ImGui::GetIO().WantCaptureMouse) return;
#endif
    if (self->preset_ == CameraPreset::kTopDown) self->preset_ = CameraPreset::kFree;
    mjv_moveCamera(i.model.get(), mjMOUSE_ZOOM, 0.0, -0.05 * dy, &i.scene, &i.camera);
  });

#if PLYWOOD_HAS_IMGUI
  if (options.panel) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the user's directory
    // After our callbacks: the backend chains to them.
    ImGui_ImplGlfw_InitForOpenGL(g.window, true);
    ImGui_ImplOpenGL2_Init();
    g.imgui = true;
  }
#endif
  SetPreset(CameraPreset::kTopDown);
}

ViewerWindow::~ViewerWindow() {
  // Xlib may not be used after a lost connection, and GL fails on a destroyed window
  // (x_connection_loss.h): nothing is freed, the process is about to end.
  if (Gone()) {
    // Still reachable (not a leak to LeakSanitizer); volatile: the store is kept.
    [[maybe_unused]] static Impl* volatile abandoned = nullptr;
    abandoned = impl_.release();
    return;
  }
  Impl& g = *impl_;
  glfwMakeContextCurrent(g.window);
#if PLYWOOD_HAS_IMGUI
  if (g.imgui) {
    ImGui_ImplOpenGL2_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
#endif
  mjr_freeContext(&g.con);
  mjv_freeScene(&g.scene);
  glfwDestroyWindow(g.window);
  glfwTerminate();
}

void ViewerWindow::HandleKey(int key, int action, int mods) {
  if (action == GLFW_PRESS && key == GLFW_KEY_T) SetPreset(CameraPreset::kTopDown);
  if (key_handler_) key_handler_(key, action, mods);
}

void ViewerWindow::PollEvents() { glfwPollEvents(); }

bool ViewerWindow::CloseRequested() const { return Gone() || glfwWindowShouldClose(impl_->window); }

bool ViewerWindow::Gone() const { return XLossSoFar() != XLoss::kNone; }

void ViewerWindow::SetTitle(const std::string& title) {
  if (!Gone()) glfwSetWindowTitle(impl_->window, title.c_str());
}

// A destroyed window's size is whatever GLFW's failed query left (uninitialised): 0 then.
int ViewerWindow::framebuffer_width() const {
  int width = 0, height = 0;
  glfwGetFramebufferSize(impl_->window, &width, &height);
  return Gone() ? 0 : width;
}

int ViewerWindow::framebuffer_height() const {
  int width = 0, height = 0;
  glfwGetFramebufferSize(impl_->window, &width, &height);
  return Gone() ? 0 : height;
}

void ViewerWindow::SetPreset(CameraPreset preset, int follow_body_id) {
  Impl& g = *impl_;
  preset_ = preset;
  const render::WorldBounds& b = g.world_bounds;
  if (preset == CameraPreset::kFollow) {
    g.camera.type = mjCAMERA_TRACKING;
    g.camera.trackbodyid = follow_body_id;
    g.camera.distance = 4.0;
    g.camera.elevation = -35.0;
    g.camera.azimuth = 180.0;
    return;
  }
  // Top-down (and the free camera it starts from): looking straight down on the world's centre.
  g.camera.type = mjCAMERA_FREE;
  g.camera.lookat[0] = b.centre().x();
  g.camera.lookat[1] = b.centre().y();
  g.camera.lookat[2] = 0.0;
  g.camera.azimuth = 90.0;
  g.camera.elevation = -89.9;
  g.camera.distance = 1.2 * std::max(b.width_m(), b.height_m());
}

mjvScene& ViewerWindow::BeginFrame(mjData* d) {
  Impl& g = *impl_;
  glfwMakeContextCurrent(g.window);
  overlay_primitives_.Clear();
  mjv_updateScene(g.model.get(), d, &g.option, nullptr, &g.camera, mjCAT_ALL, &g.scene);
  if (preset_ == CameraPreset::kTopDown) {
    // The world framed exactly in the window, as TopDownRenderer frames a snapshot.
    const int width = std::max(1, framebuffer_width()), height = std::max(1, framebuffer_height());
    const render::WorldBounds& b = g.world_bounds;
    render::TopDownFrame frame;
    frame.width_px = width;
    frame.height_px = height;
    const double pixels_per_m = std::min(width / b.width_m(), height / b.height_m());
    const Eigen::Vector2d half(0.5 * width / pixels_per_m, 0.5 * height / pixels_per_m);
    frame.shown = {b.centre().x() - half.x(), b.centre().x() + half.x(), b.centre().y() - half.y(),
                   b.centre().y() + half.y()};
    frame.world_to_pixel = {pixels_per_m, frame.shown.x_min_m, frame.shown.y_max_m};
    const double camera_height_m = render::TopDownCameraHeightM(std::max(width, height), g.z_top_m);
    g.top_down_camera = render::MakeTopDownGlCamera(frame, camera_height_m, g.z_top_m);
    g.top_down_map = render::FloorMappingOf(g.top_down_camera, width, height);
    g.scene.camera[0] = g.top_down_camera;
    g.scene.camera[1] = g.top_down_camera;
  }
  return g.scene;
}

void ViewerWindow::Finish(const std::string& top_left, const std::string& bottom_right,
                          const std::function<void()>& panel) {
  Impl& g = *impl_;
  // A window that went away meanwhile (x_connection_loss.h) is not drawn on again.
  const mjrRect viewport{0, 0, framebuffer_width(), framebuffer_height()};
  if (Gone()) return;
  mjr_render(viewport, &g.scene, &g.con);
  DrawOverlayPrimitives(overlay_primitives_, g.con.lineWidth);
  // mjr_overlay takes two columns; each block line is "title\tvalue".
  const auto text = [&](int grid, const std::string& block) {
    if (block.empty()) return;
    std::string titles, values;
    std::size_t start = 0;
    while (start < block.size()) {
      std::size_t end = block.find('\n', start);
      if (end == std::string::npos) end = block.size();
      const std::string line = block.substr(start, end - start);
      const std::size_t tab = line.find('\t');
      const std::string separator = start == 0 ? "" : "\n";
      titles += separator + line.substr(0, tab);
      values += separator + (tab == std::string::npos ? "" : line.substr(tab + 1));
      start = end + 1;
    }
    mjr_overlay(mjFONT_NORMAL, grid, viewport, titles.c_str(), values.c_str(), &g.con);
  };
  text(mjGRID_TOPLEFT, top_left);
  text(mjGRID_BOTTOMRIGHT, bottom_right);
#if PLYWOOD_HAS_IMGUI
  if (g.imgui && panel) {
    ImGui_ImplOpenGL2_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    if (Gone()) return;  // its window size is garbage: Dear ImGui would assert
    ImGui::NewFrame();
    panel();
    ImGui::Render();
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
  }
#else
  (void)panel;
#endif
  if (capture_) {
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(viewport.width) * viewport.height * 3);
    mjr_readPixels(rgb.data(), nullptr, viewport, &g.con);
    captured_ = render::FromBottomUpRows(rgb, viewport.width, viewport.height);
  }
  glfwSwapBuffers(g.window);
}

render::WorldToPixel ViewerWindow::TopDownMapping() const { return impl_->top_down_map; }

}  // namespace plywood::viewer
