#pragma once

#include <mujoco/mujoco.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "render/png_image.h"
#include "render/world_to_pixel.h"

namespace plywood::render {

struct TopDownOptions {
  int longer_side_px = 1024;  // picture size along the longer side of the framed bounds
  double margin_m = 0.25;     // floor shown beyond the framed bounds on every side
  bool show_robot = true;     // draw geom group 3 (sim::Scene::kRobotGeomGroup)

  // @throws std::invalid_argument whose message starts with the offending field's name.
  void Validate() const;
};

// A top-down picture and the exact map from floor coordinates to its pixels.
struct TopDownImage {
  RgbImage image;
  WorldToPixel world_to_pixel;
};

// The GL camera for a top-down view of `frame`: `height_m` above the floor's centre, looking down
// with world +y up the picture, its frustum cut so the floor plane fills the picture exactly.
// MuJoCo 2.2.2 has no orthographic projection, so the camera stands far away: a point `h` above
// the floor at `r` from the centre appears displaced by r * h / (height_m - h), which
// TopDownCameraHeightM keeps below a quarter pixel. `z_top_m` bounds the scene's height (near
// plane).
mjvGLCamera MakeTopDownGlCamera(const TopDownFrame& frame, double height_m, double z_top_m);
double TopDownCameraHeightM(int longer_side_px, double z_top_m);

// The part of `whole` (a camera for a width_px x height_px viewport) that a viewport of `width` x
// `height` pixels shows when it is the box of the whole picture whose lower-left pixel is (x,
// y_from_bottom), GL's rows counted from the bottom.
mjvGLCamera CutTopDownGlCamera(const mjvGLCamera& whole, int width_px, int height_px, int x,
                               int y_from_bottom, int width, int height);

// The floor-plane map a downward-looking GL camera produces on a `width_px` x `height_px` viewport,
// following mjr_render's projection (glFrustum with the horizontal half-width set by the aspect).
// @pre camera looks along -z with up = +y.
WorldToPixel FloorMappingOf(const mjvGLCamera& camera, int width_px, int height_px);

// A rectangle of pixels: columns [x, x + width), image rows [y, y + height) counted from the top.
struct PixelBox {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
};

// Renders top-down views of one model through MuJoCo's OpenGL renderer in an offscreen context.
// Construction copies the model (to size the offscreen buffer and light the scene from above) and
// builds the GL resources once, so rendering many frames is cheap. Not copyable; one per thread:
// construct, render and destroy it on the same thread (its GL context is current there).
class TopDownRenderer {
 public:
  // Frames `bounds` (plus options.margin_m).
  // @throws std::invalid_argument on bad options or bounds, std::runtime_error when no offscreen
  // GL context can be made or MuJoCo cannot render offscreen.
  TopDownRenderer(const mjModel* m, const WorldBounds& bounds, const TopDownOptions& options = {});
  ~TopDownRenderer();
  TopDownRenderer(const TopDownRenderer&) = delete;
  TopDownRenderer& operator=(const TopDownRenderer&) = delete;

  // Renders the scene in `d` (which must belong to the model given at construction, with
  // kinematics computed, as after mj_forward or mj_step).
  // @throws std::runtime_error when GL reports an error.
  TopDownImage Render(mjData* d);

  // Draws the scene in `d` without what moves (the geoms IsStaticGeom takes only: welded to the
  // world, not by way of a mocap body) over the whole picture and keeps it, with the scene's
  // lights, for RenderOverStaticFrame. Compiles llvmpipe's shaders (a scene's first draw does), so
  // a later Render is quicker; meant for a thread that has time while the run goes on.
  // @throws std::runtime_error when GL reports an error.
  void KeepStaticFrame(mjData* d);
  // Render(d)'s picture, drawn as the kept static frame with only the box round the moving geoms
  // drawn anew from `d` (the geoms reaching the box, through a frustum cut to it): a final frame
  // after a run then rasterises a few thousand pixels instead of the whole picture. A whole Render
  // when no static frame was kept for this framing, when something drawn is not a geom of the
  // model (a skin, a decoration), when a light is not where it was for the static frame, or when
  // the box is over a quarter of the picture. Pixels beyond the box are the static frame's, which
  // are Render's: nothing that moves covers them. Inside it the cut frustum can round a vertex
  // differently from the whole one, so a pixel on an edge there may differ (docs/performance.md,
  // "Stop 67").
  // @throws std::runtime_error when GL reports an error.
  TopDownImage RenderOverStaticFrame(mjData* d);
  // Frames `bounds` instead (same options), keeping the GL context and its compiled shaders.
  // Returns false, changing nothing, when that picture is larger than the buffers made for the
  // first framing (make a new renderer then). @throws std::invalid_argument on bad bounds.
  [[nodiscard]] bool Reframe(const WorldBounds& bounds);

  const TopDownFrame& frame() const { return frame_; }

 private:
  void Aim();  // points the cameras at frame_ and sets its floor map
  void Draw(mjData* d, const mjrRect& viewport);
  void UpdateScene(mjData* d);
  void DrawScene(const mjrRect& viewport, const mjvGLCamera& camera);
  std::vector<std::uint8_t> ReadPixels(const mjrRect& viewport);
  // The pixel box (image rows, top down) round every moving geom of the scene last updated, or
  // nothing when something moving is not a geom of the model.
  std::optional<PixelBox> MovingBox() const;
  // Leaves out of the scene last updated the geoms whose bounding circle misses `box`.
  void KeepOnlyGeomsReaching(const PixelBox& box);

  struct Gl;
  TopDownOptions options_;
  TopDownFrame frame_;
  std::unique_ptr<Gl> gl_;
  // KeepStaticFrame's picture (GL rows, bottom up) and the framing it was drawn for.
  std::vector<std::uint8_t> static_rgb_;
  std::optional<TopDownFrame> static_frame_;
  std::vector<mjvLight> static_lights_;  // the lights as they were then
};

// The same view drawn without GL: the floor colour, then every visible geom's footprint from above
// (static ones from the model, moving ones from `d`), lowest first. Used when offscreen rendering
// is unavailable; the picture is flatter but the mapping is identical.
TopDownImage RenderTopDownSoftware(const mjModel* m, const mjData* d, const WorldBounds& bounds,
                                   const TopDownOptions& options = {});

}  // namespace plywood::render
