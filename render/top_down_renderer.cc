#include "render/top_down_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "msgs/shortest_number.h"
#include "render/geom_footprint.h"
#include "render/image_ops.h"
#include "render/model_textures.h"
#include "render/offscreen_context.h"
#include "render/overlay.h"
#include "sim/world/mujoco_handles.h"

namespace plywood::render {
namespace {

// A plane's rendering grid spacing so large that MuJoCo draws the floor as 2 x 2 quads.
constexpr double kFloorGridSpacingM = 1000.0;

constexpr int kRobotGeomGroup = 3;

// Beyond a geom's bounding circle on the floor map: the projection's parallax (< 0.18 px:
// TopDownCameraHeightM) and an edge's multisamples (< 1 px).
constexpr double kFootprintMarginPx = 2.0;

// Keeps, in order, the scene's geoms `keep` accepts.
template <typename Keep>
void KeepSceneGeoms(mjvScene& scene, Keep keep) {
  int kept = 0;
  for (int i = 0; i < scene.ngeom; ++i) {
    if (keep(scene.geoms[i])) scene.geoms[kept++] = scene.geoms[i];
  }
  scene.ngeom = kept;
}  // sim::Scene::kRobotGeomGroup, without pulling in scene.h

bool GroupShown(const mjModel* m, int g, bool show_robot) {
  const int group = m->geom_group[g];
  return (group >= 0 && group <= 2) || (show_robot && group == kRobotGeomGroup);
}

TopDownFrame FrameFor(const WorldBounds& bounds, const TopDownOptions& options) {
  options.Validate();
  return FrameBounds(bounds.Padded(options.margin_m), options.longer_side_px);
}

}  // namespace

void TopDownOptions::Validate() const {
  if (longer_side_px < 16 || longer_side_px > 8192) {
    throw std::invalid_argument("longer_side_px: must be in [16, 8192], got " +
                                std::to_string(longer_side_px));
  }
  if (!(margin_m >= 0.0) || !std::isfinite(margin_m)) {
    throw std::invalid_argument("margin_m: must be >= 0, got " + std::to_string(margin_m));
  }
}

double TopDownCameraHeightM(int longer_side_px, double z_top_m) {
  // Parallax of a point h high at the picture's corner (r = 0.71 of the longer side L, with
  // longer_side_px / L pixels per metre) is 0.71 * longer_side_px * h / D pixels; D = 4 * px * h
  // keeps it under 0.18 px. Assume at least 1 m of height for the robot on top of the world.
  return std::max(100.0, 4.0 * longer_side_px * std::max(z_top_m, 1.0));
}

mjvGLCamera MakeTopDownGlCamera(const TopDownFrame& frame, double height_m, double z_top_m) {
  const Eigen::Vector2d centre = frame.shown.centre();
  mjvGLCamera camera{};
  camera.pos[0] = static_cast<float>(centre.x());
  camera.pos[1] = static_cast<float>(centre.y());
  camera.pos[2] = static_cast<float>(height_m);
  camera.forward[2] = -1.0f;
  camera.up[1] = 1.0f;
  // Near and far hug the scene: depth precision stays high although the camera is far away.
  const double near_m = height_m - std::max(z_top_m, 1.0) - 1.0;
  const double half_height_floor_m = 0.5 * frame.height_px / frame.world_to_pixel.pixels_per_m;
  camera.frustum_near = static_cast<float>(near_m);
  camera.frustum_far = static_cast<float>(height_m + 1.0);
  camera.frustum_center = 0.0f;
  camera.frustum_top = static_cast<float>(half_height_floor_m * near_m / height_m);
  camera.frustum_bottom = -camera.frustum_top;
  return camera;
}

WorldToPixel FloorMappingOf(const mjvGLCamera& camera, int width_px, int height_px) {
  // Similar triangles: the near-plane window scales by distance / near onto the floor (z = 0).
  const double to_floor = static_cast<double>(camera.pos[2]) / camera.frustum_near;
  const double half_height_m = 0.5 * (camera.frustum_top - camera.frustum_bottom) * to_floor;
  const double pixels_per_m = height_px / (2.0 * half_height_m);
  const double centre_x_m = camera.pos[0] + camera.frustum_center * to_floor;
  const double centre_y_m =
      camera.pos[1] + 0.5 * (camera.frustum_top + camera.frustum_bottom) * to_floor;
  return {pixels_per_m, centre_x_m - 0.5 * width_px / pixels_per_m, centre_y_m + half_height_m};
}

struct TopDownRenderer::Gl {
  // Declared first so it is destroyed last, after the GL objects below are freed.
  OffscreenContext context;
  sim::MjModelPtr model;
  mjvScene scene;
  mjrContext con;
  mjvOption option;
  mjvCamera camera;
  mjvGLCamera gl_camera;
  double z_top_m = 0.0;

  Gl(int width, int height) : context(width, height) {
    mjv_defaultScene(&scene);
    mjr_defaultContext(&con);
  }
  ~Gl() {
    try {
      context.MakeCurrent();
    } catch (const std::exception&) {
    }
    mjr_freeContext(&con);
    mjv_freeScene(&scene);
  }
};

TopDownRenderer::TopDownRenderer(const mjModel* m, const WorldBounds& bounds,
                                 const TopDownOptions& options)
    : options_(options), frame_(FrameFor(bounds, options)) {
  if (!kHasOffscreenRendering) {
    throw std::runtime_error("offscreen rendering: this build has no OSMesa");
  }
  gl_ = std::make_unique<Gl>(frame_.width_px, frame_.height_px);
  gl_->model.reset(mj_copyModel(nullptr, m));
  if (!gl_->model) throw std::runtime_error("offscreen rendering: mj_copyModel failed");
  mjModel* copy = gl_->model.get();
  // The offscreen buffer is sized from the model (default 640 x 480): raise it to the picture.
  copy->vis.global.offwidth = std::max(copy->vis.global.offwidth, frame_.width_px);
  copy->vis.global.offheight = std::max(copy->vis.global.offheight, frame_.height_px);
  // A headlight straight down with ambient + diffuse = 0.8: alone it shows upward faces at 80% of
  // their colour, leaving headroom for the world's own lights before colours saturate.
  for (int i = 0; i < 3; ++i) {
    copy->vis.headlight.ambient[i] = 0.3f;
    copy->vis.headlight.diffuse[i] = 0.5f;
    copy->vis.headlight.specular[i] = 0.0f;
  }
  copy->vis.headlight.active = 1;
  // No shadow map: mjr_makeContext would zero-fill the default 4096^2 one (most of a run's wall
  // time), and a straight-down headlight casts no shadow the picture could show.
  copy->vis.quality.shadowsize = 0;
  // MuJoCo draws a plane as a grid of quads geom_size[2] apart: the office's floor is ~38k
  // triangles, most of the final frame's rasterising after the run (docs/performance.md). A flat
  // floor lit straight down looks the same as two quads per axis; only the texture's interpolation
  // can round one colour level differently in a few pixels.
  for (int g = 0; g < copy->ngeom; ++g) {
    if (copy->geom_type[g] == mjGEOM_PLANE) copy->geom_size[3 * g + 2] = kFloorGridSpacingM;
  }

  mjv_makeScene(copy, &gl_->scene, std::max(1000, 2 * copy->ngeom + 100));
  // Textures with their mipmaps computed here: no blit shader for llvmpipe to compile.
  MakeContextWithMipmapChains(copy, &gl_->con, mjFONTSCALE_100);
  mjr_setBuffer(mjFB_OFFSCREEN, &gl_->con);
  if (gl_->con.currentBuffer != mjFB_OFFSCREEN) {
    throw std::runtime_error("offscreen rendering: MuJoCo could not bind its offscreen buffer");
  }
  const mjrRect max_viewport = mjr_maxViewport(&gl_->con);
  if (max_viewport.width < frame_.width_px || max_viewport.height < frame_.height_px) {
    throw std::runtime_error("offscreen rendering: buffer " + std::to_string(max_viewport.width) +
                             " x " + std::to_string(max_viewport.height) + " is smaller than " +
                             std::to_string(frame_.width_px) + " x " +
                             std::to_string(frame_.height_px));
  }
  gl_->scene.flags[mjRND_SKYBOX] = 0;
  gl_->scene.flags[mjRND_FOG] = 0;
  gl_->scene.flags[mjRND_HAZE] = 0;
  gl_->scene.flags[mjRND_REFLECTION] = 0;

  mjv_defaultOption(&gl_->option);
  for (int i = 0; i < mjNGROUP; ++i) {
    gl_->option.geomgroup[i] = (i <= 2) || (options_.show_robot && i == kRobotGeomGroup);
    gl_->option.sitegroup[i] = 0;  // sensor sites would clutter the map
  }
  gl_->z_top_m = StaticGeometryExtent(copy).z_max_m;
  Aim();
}

bool TopDownRenderer::Reframe(const WorldBounds& bounds) {
  const TopDownFrame frame = FrameFor(bounds, options_);
  const mjrRect max_viewport = mjr_maxViewport(&gl_->con);
  if (frame.width_px > max_viewport.width || frame.height_px > max_viewport.height ||
      frame.width_px > gl_->context.width() || frame.height_px > gl_->context.height()) {
    return false;
  }
  frame_ = frame;
  Aim();
  return true;
}

void TopDownRenderer::Aim() {
  const double height_m = TopDownCameraHeightM(options_.longer_side_px, gl_->z_top_m);
  gl_->gl_camera = MakeTopDownGlCamera(frame_, height_m, gl_->z_top_m);
  // The abstract camera only places the headlight (mjv_updateScene derives it from this camera);
  // the GL camera above replaces the projection it would produce.
  mjv_defaultCamera(&gl_->camera);
  gl_->camera.type = mjCAMERA_FREE;
  gl_->camera.lookat[0] = gl_->gl_camera.pos[0];
  gl_->camera.lookat[1] = gl_->gl_camera.pos[1];
  gl_->camera.lookat[2] = 0.0;
  gl_->camera.azimuth = 90.0;
  gl_->camera.elevation = -90.0;
  gl_->camera.distance = height_m;
  // The floor map this camera yields is what we report, so the two cannot disagree.
  frame_.world_to_pixel = FloorMappingOf(gl_->gl_camera, frame_.width_px, frame_.height_px);
  // The camera is in floats: a frame reaching past their range (a plug-in's estimate at 1e300 m)
  // gives an infinite camera and a NaN floor map. The caller then draws in software (doubles).
  const WorldToPixel& map = frame_.world_to_pixel;
  if (!std::isfinite(map.pixels_per_m) || !(map.pixels_per_m > 0.0) ||
      !std::isfinite(map.x_left_m) || !std::isfinite(map.y_top_m)) {
    const double wide_m = std::max(frame_.shown.width_m(), frame_.shown.height_m());
    throw std::runtime_error("offscreen rendering: a frame " + msgs::ShortestNumber(wide_m) +
                             " m wide does not fit OpenGL's float camera");
  }
}

TopDownRenderer::~TopDownRenderer() = default;

void TopDownRenderer::UpdateScene(mjData* d) {
  gl_->context.MakeCurrent();
  mjv_updateScene(gl_->model.get(), d, &gl_->option, nullptr, &gl_->camera, mjCAT_ALL, &gl_->scene);
}

void TopDownRenderer::DrawScene(const mjrRect& viewport, const mjvGLCamera& camera) {
  mjr_setBuffer(mjFB_OFFSCREEN, &gl_->con);
  gl_->scene.camera[0] = camera;
  gl_->scene.camera[1] = camera;
  mjr_render(viewport, &gl_->scene, &gl_->con);
}

void TopDownRenderer::Draw(mjData* d, const mjrRect& viewport) {
  UpdateScene(d);
  DrawScene(viewport, gl_->gl_camera);
}

std::vector<std::uint8_t> TopDownRenderer::ReadPixels(const mjrRect& viewport) {
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(viewport.width) * viewport.height * 3);
  mjr_readPixels(rgb.data(), nullptr, viewport, &gl_->con);
  if (const int error = mjr_getError(); error != 0) {
    throw std::runtime_error("offscreen rendering: OpenGL error " + std::to_string(error));
  }
  return rgb;
}

void TopDownRenderer::KeepStaticFrame(mjData* d) {
  UpdateScene(d);
  const mjModel* m = gl_->model.get();
  mjvScene& scene = gl_->scene;
  KeepSceneGeoms(scene, [m](const mjvGeom& geom) {
    return geom.objtype == mjOBJ_GEOM && IsStaticGeom(m, geom.objid);
  });
  static_lights_.assign(scene.lights, scene.lights + scene.nlight);
  const mjrRect viewport{0, 0, frame_.width_px, frame_.height_px};
  DrawScene(viewport, gl_->gl_camera);
  static_rgb_ = ReadPixels(viewport);
  static_frame_ = frame_;
}

std::optional<PixelBox> TopDownRenderer::MovingBox() const {
  const mjModel* m = gl_->model.get();
  // A light not where the static frame had it lights static pixels differently: one on a moving
  // body, but also one of the world that tracks a moving body's centre of mass or turns to it.
  const mjvScene& scene = gl_->scene;
  if (scene.nlight != static_cast<int>(static_lights_.size())) return std::nullopt;
  for (int l = 0; l < scene.nlight; ++l) {
    const mjvLight& now = scene.lights[l];
    const mjvLight& kept = static_lights_[l];
    if (!std::equal(now.pos, now.pos + 3, kept.pos) ||
        !std::equal(now.dir, now.dir + 3, kept.dir)) {
      return std::nullopt;
    }
  }
  const WorldToPixel& map = frame_.world_to_pixel;
  double u_min = std::numeric_limits<double>::infinity(), v_min = u_min;
  double u_max = -u_min, v_max = -u_min;
  for (int i = 0; i < gl_->scene.ngeom; ++i) {
    const mjvGeom& geom = gl_->scene.geoms[i];
    // A site, a tendon, a skin (mjOBJ_SKIN, moving with its bones), a label: no bound.
    if (geom.objtype != mjOBJ_GEOM) return std::nullopt;
    if (IsStaticGeom(m, geom.objid)) continue;
    const double radius_m = m->geom_rbound[geom.objid];
    if (!(radius_m > 0.0) || !std::isfinite(radius_m)) return std::nullopt;  // a moving plane
    const Eigen::Vector2d centre = map.ToPixel({geom.pos[0], geom.pos[1]});
    if (!centre.allFinite()) return std::nullopt;  // a state gone non-finite: draw it whole
    const double radius_px = radius_m * map.pixels_per_m;
    u_min = std::min(u_min, centre.x() - radius_px);
    u_max = std::max(u_max, centre.x() + radius_px);
    v_min = std::min(v_min, centre.y() - radius_px);
    v_max = std::max(v_max, centre.y() + radius_px);
  }
  if (!(u_max >= u_min)) return PixelBox{};  // nothing moves: the static frame is the picture
  if (!std::isfinite(u_min + u_max + v_min + v_max)) return std::nullopt;
  const auto clamp = [](double v, int hi) {
    return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(hi)));
  };
  PixelBox box;
  box.x = clamp(std::floor(u_min - kFootprintMarginPx), frame_.width_px);
  box.y = clamp(std::floor(v_min - kFootprintMarginPx), frame_.height_px);
  box.width = clamp(std::ceil(u_max + kFootprintMarginPx), frame_.width_px) - box.x;
  box.height = clamp(std::ceil(v_max + kFootprintMarginPx), frame_.height_px) - box.y;
  return box;
}

void TopDownRenderer::KeepOnlyGeomsReaching(const PixelBox& box) {
  // A geom whose bounding circle misses the box draws no pixel of it: leaving it out saves its
  // draw (llvmpipe validates and sets up every draw and shades every vertex on the CPU). Planes
  // (no bound) stay.
  const mjModel* m = gl_->model.get();
  const WorldToPixel& map = frame_.world_to_pixel;
  KeepSceneGeoms(gl_->scene, [&](const mjvGeom& geom) {
    const double radius_m = m->geom_rbound[geom.objid];
    if (!(radius_m > 0.0)) return true;
    const Eigen::Vector2d centre = map.ToPixel({geom.pos[0], geom.pos[1]});
    const double radius_px = radius_m * map.pixels_per_m + kFootprintMarginPx;
    return centre.x() + radius_px >= box.x && centre.x() - radius_px <= box.x + box.width &&
           centre.y() + radius_px >= box.y && centre.y() - radius_px <= box.y + box.height;
  });
}

mjvGLCamera CutTopDownGlCamera(const mjvGLCamera& whole, int width_px, int height_px, int x,
                               int y_from_bottom, int width, int height) {
  // The whole near-plane window is width_px x height_px pixels of (top - bottom) / height_px each
  // (mjr_render sets the half-width from the viewport's aspect); the cut is the box's part of it.
  const double per_px = (static_cast<double>(whole.frustum_top) - whole.frustum_bottom) / height_px;
  const double left = whole.frustum_center - 0.5 * per_px * width_px;
  mjvGLCamera cut = whole;
  cut.frustum_center = static_cast<float>(left + (x + 0.5 * width) * per_px);
  cut.frustum_bottom = static_cast<float>(whole.frustum_bottom + y_from_bottom * per_px);
  cut.frustum_top = static_cast<float>(whole.frustum_bottom + (y_from_bottom + height) * per_px);
  return cut;
}

TopDownImage TopDownRenderer::RenderOverStaticFrame(mjData* d) {
  const bool same_framing =
      static_frame_ && static_frame_->width_px == frame_.width_px &&
      static_frame_->height_px == frame_.height_px &&
      static_frame_->world_to_pixel.pixels_per_m == frame_.world_to_pixel.pixels_per_m &&
      static_frame_->world_to_pixel.x_left_m == frame_.world_to_pixel.x_left_m &&
      static_frame_->world_to_pixel.y_top_m == frame_.world_to_pixel.y_top_m;
  if (!same_framing) return Render(d);
  UpdateScene(d);
  const std::optional<PixelBox> box = MovingBox();
  const std::size_t whole = static_cast<std::size_t>(frame_.width_px) * frame_.height_px;
  if (!box || 4 * static_cast<std::size_t>(box->width) * box->height > whole) {
    const mjrRect viewport{0, 0, frame_.width_px, frame_.height_px};
    DrawScene(viewport, gl_->gl_camera);
    return {FromBottomUpRows(ReadPixels(viewport), frame_.width_px, frame_.height_px),
            frame_.world_to_pixel};
  }
  RgbImage image = FromBottomUpRows(static_rgb_, frame_.width_px, frame_.height_px);
  if (box->width > 0 && box->height > 0) {
    KeepOnlyGeomsReaching(*box);
    const int y_from_bottom = frame_.height_px - box->y - box->height;
    const mjrRect viewport{0, 0, box->width, box->height};
    DrawScene(viewport, CutTopDownGlCamera(gl_->gl_camera, frame_.width_px, frame_.height_px,
                                           box->x, y_from_bottom, box->width, box->height));
    const std::vector<std::uint8_t> rgb = ReadPixels(viewport);
    const std::size_t row_bytes = static_cast<std::size_t>(box->width) * 3;
    for (int row = 0; row < box->height; ++row) {
      // GL rows count from the bottom.
      std::memcpy(image.At(box->x, box->y + box->height - 1 - row), rgb.data() + row * row_bytes,
                  row_bytes);
    }
  }
  return {std::move(image), frame_.world_to_pixel};
}

TopDownImage TopDownRenderer::Render(mjData* d) {
  const mjrRect viewport{0, 0, frame_.width_px, frame_.height_px};
  Draw(d, viewport);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(frame_.width_px) * frame_.height_px * 3);
  mjr_readPixels(rgb.data(), nullptr, viewport, &gl_->con);
  if (const int error = mjr_getError(); error != 0) {
    throw std::runtime_error("offscreen rendering: OpenGL error " + std::to_string(error));
  }
  return {FromBottomUpRows(rgb, frame_.width_px, frame_.height_px), frame_.world_to_pixel};
}

TopDownImage RenderTopDownSoftware(const mjModel* m, const mjData* d, const WorldBounds& bounds,
                                   const TopDownOptions& options) {
  const TopDownFrame frame = FrameFor(bounds, options);
  TopDownImage out{RgbImage(frame.width_px, frame.height_px), frame.world_to_pixel};
  Rgb floor{200, 200, 200};
  std::vector<GeomFootprint> footprints;
  for (int g = 0; g < m->ngeom; ++g) {
    if (!GroupShown(m, g, options.show_robot)) continue;
    // Invisible geoms (alpha 0, no material) are collision shapes only, e.g. a bumper ring.
    if (m->geom_matid[g] < 0 && m->geom_rgba[4 * g + 3] <= 0.0f) continue;
    const bool is_static = IsStaticGeom(m, g);
    if (!is_static && d == nullptr) continue;
    Eigen::Isometry3d X_WG = Eigen::Isometry3d::Identity();
    if (is_static) {
      X_WG = StaticGeomPose(m, g);
    } else {
      X_WG.translation() =
          Eigen::Vector3d(d->geom_xpos[3 * g], d->geom_xpos[3 * g + 1], d->geom_xpos[3 * g + 2]);
      X_WG.linear() =
          Eigen::Map<const Eigen::Matrix<mjtNum, 3, 3, Eigen::RowMajor>>(d->geom_xmat + 9 * g);
    }
    GeomFootprint footprint = FootprintOf(m, g, X_WG);
    if (m->geom_type[g] == mjGEOM_PLANE) {
      floor = footprint.colour;
      continue;
    }
    footprints.push_back(std::move(footprint));
  }
  Fill(out.image, floor);
  std::stable_sort(
      footprints.begin(), footprints.end(),
      [](const GeomFootprint& a, const GeomFootprint& b) { return a.z_top_m < b.z_top_m; });
  for (const GeomFootprint& f : footprints) {
    std::vector<Eigen::Vector2d> outline_px;
    for (const Eigen::Vector2d& v : f.outline_W)
      outline_px.push_back(frame.world_to_pixel.ToPixel(v));
    FillPolygonPx(out.image, outline_px, f.colour);
    if (outline_px.size() >= 3) {
      outline_px.push_back(outline_px.front());
      const Rgb edge{static_cast<std::uint8_t>(f.colour.r * 0.6),
                     static_cast<std::uint8_t>(f.colour.g * 0.6),
                     static_cast<std::uint8_t>(f.colour.b * 0.6)};
      DrawPolylinePx(out.image, outline_px, edge, 1.0);
    }
  }
  return out;
}

}  // namespace plywood::render
