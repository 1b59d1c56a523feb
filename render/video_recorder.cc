#include "render/video_recorder.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "render/bitmap_font.h"
#include "render/geom_footprint.h"
#include "render/offscreen_context.h"
#include "render/overlay.h"
#include "render/scale_bar.h"

namespace plywood::render {

void VideoOptions::Validate() const {
  if (!(fps >= 1.0 && fps <= 60.0)) {
    throw std::invalid_argument("fps: must be in [1, 60], got " + std::to_string(fps));
  }
  if (longer_side_px < 64 || longer_side_px > 4096) {
    throw std::invalid_argument("longer_side_px: must be in [64, 4096], got " +
                                std::to_string(longer_side_px));
  }
}

VideoRecorder::VideoRecorder(const std::filesystem::path& path, const VideoOptions& options)
    : options_((options.Validate(), options)), encoder_(path, options.fps) {}

VideoRecorder::~VideoRecorder() = default;

bool VideoRecorder::AfterStep(const sim::ExperimentRunner& runner) {
  // Frame k shows the first state at or after k / fps (steps rarely land on it exactly).
  const double t = runner.scene().time_s();
  while (next_frame_ / options_.fps <= t + 1e-9) {
    AddFrame(runner);
    ++next_frame_;
  }
  return true;
}

void VideoRecorder::RunFinished(const sim::ExperimentRunner& runner) {
  AfterStep(runner);
  encoder_.Close();
}

void VideoRecorder::AddFrame(const sim::ExperimentRunner& runner) {
  const mjModel* m = runner.scene().model();
  // mjv_updateScene only reads the data; its signature predates const-correctness.
  mjData* d = const_cast<mjData*>(runner.scene().data());
  TopDownOptions view;
  view.longer_side_px = options_.longer_side_px;
  const WorldBounds bounds = StaticGeometryExtent(m).bounds;
  if (!renderer_tried_) {
    renderer_tried_ = true;
    if (OffscreenRenderingAvailable()) {
      try {
        renderer_ = std::make_unique<TopDownRenderer>(m, bounds, view);
        // What does not move, drawn once: each frame then draws only the box round the robot
        // (TopDownRenderer::RenderOverStaticFrame; the frames' bytes are the encoder's anyway).
        renderer_->KeepStaticFrame(d);
      } catch (const std::runtime_error& e) {
        // As the line says: a renderer whose static frame failed is dropped, not drawn with.
        renderer_.reset();
        std::fprintf(stderr, "plywood: video frames drawn in software (%s)\n", e.what());
      }
    }
  }
  TopDownImage frame =
      renderer_ ? renderer_->RenderOverStaticFrame(d) : RenderTopDownSoftware(m, d, bounds, view);
  const WorldToPixel& map = frame.world_to_pixel;
  const sim::RunRecord& record = runner.record();
  if (!record.laser.empty()) {
    const sim::LaserRecord& last = record.laser.back();
    const msgs::Pose2D X_WS = last.X_WR_truth * last.scan.X_RS;
    const Eigen::Vector2d origin(X_WS.x_m, X_WS.y_m);
    for (std::size_t i = 0; i < last.scan.ranges_m.size(); ++i) {
      if (!last.scan.IsReturn(i)) continue;
      const double a = X_WS.theta_rad + last.scan.BeamAngleRad(i);
      const double r = last.scan.ranges_m[i];
      DrawPoint(frame.image, map, origin + r * Eigen::Vector2d(std::cos(a), std::sin(a)),
                colours::kOrange, 1.5);
    }
  }
  std::vector<PathOverlay> paths(1 + record.estimator_names.size());
  paths[0].colour = colours::kBlack;
  for (std::size_t e = 0; e < record.estimator_names.size(); ++e) {
    paths[e + 1].label = record.estimator_names[e];
    paths[e + 1].colour = colours::kPalette[e % std::size(colours::kPalette)];
  }
  paths[0].label = "ground truth";
  for (const sim::TrajectorySample& s : record.trajectory) {
    paths[0].points_W.emplace_back(s.truth.x_m, s.truth.y_m);
    for (std::size_t e = 0; e < s.estimates.size(); ++e) {
      paths[e + 1].points_W.emplace_back(s.estimates[e].x_m, s.estimates[e].y_m);
    }
  }
  DrawScaleBarAndAxes(frame.image, map);
  if (!record.trajectory.empty()) DrawPaths(frame.image, map, paths);
  char clock[48];
  std::snprintf(clock, sizeof(clock), "t = %.1f s", runner.scene().time_s());
  const int scale = frame.image.width >= 800 ? 2 : 1;
  FillRectPx(frame.image, 4, 4, 12 + TextWidthPx(clock, scale), 12 + TextHeightPx(scale),
             colours::kWhite, 0.85);
  DrawText(frame.image, 8, 8, clock, colours::kBlack, scale);
  encoder_.AddFrame(frame.image);
}

}  // namespace plywood::render
