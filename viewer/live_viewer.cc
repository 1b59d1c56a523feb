#include "viewer/live_viewer.h"

#include <GLFW/glfw3.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "render/geom_footprint.h"
#include "render/video_encoder.h"
#include "viewer/scene_overlays.h"
#include "viewer/x_connection_loss.h"

#if PLYWOOD_HAS_IMGUI
#include <imgui.h>
#endif

namespace plywood::viewer {
namespace {

constexpr double kVideoFps = 30.0;

const char* SpeedName(Speed speed) {
  switch (speed) {
    case Speed::kRealTime:
      return "1x";
    case Speed::kTenTimes:
      return "10x";
    case Speed::kUnlimited:
      return "as fast as possible";
  }
  return "";
}

}  // namespace

void LiveViewerOptions::Validate() const {
  window.Validate();
  teleop.Validate();
  if (!(max_fps >= 0.0 && max_fps <= 1000.0)) {
    throw std::invalid_argument("max_fps: must be in [0, 1000], got " + std::to_string(max_fps));
  }
}

LiveViewer::LiveViewer(const LiveViewerOptions& options) : options_(options) { options.Validate(); }

LiveViewer::~LiveViewer() {
  if (window_) SetViewedRun(ViewedRun::kNone);  // a later window (tests) starts afresh
}

void LiveViewer::Open(const sim::ExperimentRunner& runner) {
  if (window_) return;
  SetViewedRun(ViewedRun::kRunning);  // the window shows before its constructor returns
  window_ = std::make_unique<ViewerWindow>(runner.scene().model(), options_.window);
  controls_ = std::make_unique<ViewControls>(runner.config().nominal, options_.teleop);
  controls_->set_paused(options_.start_paused);
  controls_->set_speed(options_.speed);
  content_ = std::make_unique<RunContent>(runner);
  base_body_id_ = runner.scene().base_body_id();
  world_ = render::StaticGeometryExtent(runner.scene().model()).bounds;
  window_->SetKeyHandler([this](int key, int action, int) { controls_->HandleKey(key, action); });
  start_wall_ = anchor_wall_ = Clock::now();
  start_sim_s_ = anchor_sim_s_ = runner.scene().time_s();
  anchor_factor_ = controls_->SpeedFactor();
}

std::optional<msgs::WheelSpeedCommand> LiveViewer::WheelOverride() {
  return controls_ ? controls_->Teleop() : std::nullopt;
}

bool LiveViewer::AfterStep(const sim::ExperimentRunner& runner) {
  Open(runner);
  if (closed_) return false;
  const double t = runner.scene().time_s();
  const double min_frame_s = options_.max_fps > 0.0 ? 1.0 / options_.max_fps : 0.0;
  // A frame is due after 1 / max_fps. While the run must keep up (unlimited speed, or behind the
  // wall clock) also not before as long as the last frame took, so that a slow renderer (software
  // GL) takes at most half of the time from the run.
  const auto frame_due = [&](bool run_waits) {
    const double since_s = std::chrono::duration<double>(Clock::now() - last_frame_end_).count();
    return since_s >= (run_waits ? min_frame_s : std::max(min_frame_s, last_frame_cost_s_));
  };
  for (;;) {
    window_->PollEvents();
    if (window_->CloseRequested()) {
      closed_ = true;
      return false;
    }
    HandleRequests(base_body_id_);
    const double factor = controls_->SpeedFactor();
    if (controls_->paused()) {
      if (controls_->TakeStepRequest()) break;
      if (frame_due(true)) Draw(runner);
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      anchor_factor_ = -1.0;  // re-anchor the pacing when the run resumes
      continue;
    }
    if (factor != anchor_factor_) {
      anchor_factor_ = factor;
      anchor_wall_ = Clock::now();
      anchor_sim_s_ = t;
    }
    if (factor <= 0.0) break;
    const double ahead_s = (t - anchor_sim_s_) / factor -
                           std::chrono::duration<double>(Clock::now() - anchor_wall_).count();
    if (ahead_s <= 0.0) break;
    // Ahead of the wall clock: draw while waiting (the frames/s --bench reports), else sleep.
    if (frame_due(true)) {
      Draw(runner);
    } else {
      std::this_thread::sleep_for(std::chrono::duration<double>(std::min(ahead_s, 0.002)));
    }
  }
  if (frame_due(false)) Draw(runner);
  return true;
}

void LiveViewer::Draw(const sim::ExperimentRunner& runner) {
  const FrameContent& content = content_->Update(runner);
  // mjv_updateScene only reads the data; its signature predates const-correctness.
  DrawFrame(const_cast<mjData*>(runner.scene().data()), content, PanelText(runner));
}

void LiveViewer::DrawFrame(mjData* d, const FrameContent& content, const std::string& panel) {
  const Clock::time_point start = Clock::now();
  ++frames_;
  mjvScene& scene = window_->BeginFrame(d);
  AddOverlays(scene, window_->overlay_primitives(), content, *controls_, world_);

  std::string clock;
  if (controls_->overlay(Overlay::kScaleBar)) {
    const double wall_s = std::chrono::duration<double>(Clock::now() - start_wall_).count();
    char text[256];
    std::snprintf(text, sizeof(text),
                  "simulated time\t%.2f s\nreal-time factor\t%.2fx\nspeed\t%s\ndriver\t%s%s",
                  content.time_s, wall_s > 0 ? (content.time_s - start_sim_s_) / wall_s : 0.0,
                  SpeedName(controls_->speed()),
                  controls_->teleoperating() ? "keyboard (H hands back)" : "controller",
                  final_data_           ? "\nstate\trun finished"
                  : controls_->paused() ? "\nstate\tpaused"
                                        : "");
    clock = text;
    if (video_) clock += "\nrecording\t" + video_->path().string();
  }
  const std::string help = controls_->help() ? ViewControls::HelpText() : "F1\thelp";
  window_->Finish(help, clock, [&panel] {
#if PLYWOOD_HAS_IMGUI
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x - 330, 10), ImGuiCond_FirstUseEver);
    ImGui::Begin("run", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::TextUnformatted(panel.c_str());
    ImGui::End();
#else
    (void)panel;
#endif
  });
  last_frame_end_ = Clock::now();
  last_frame_cost_s_ = std::chrono::duration<double>(last_frame_end_ - start).count();
  if (video_) {
    try {
      video_->AddFrame(window_->Screenshot());
    } catch (const std::runtime_error& e) {
      std::cerr << "plywood: " << e.what() << "\n";
      video_.reset();
    }
  }
}

void LiveViewer::RunFinished(const sim::ExperimentRunner& runner) {
  if (!window_) return;
  final_content_ = content_->Update(runner);
  final_panel_ = PanelText(runner);
  final_data_.reset(mj_copyData(nullptr, runner.scene().model(), runner.scene().data()));
  // From here a lost window or X display no longer loses the run (x_connection_loss.h); the title
  // tells the user (and the tests) that the results are safe.
  SetViewedRun(ViewedRun::kFinished);
  window_->SetTitle(options_.window.title + ": run finished");
  // Now, before the protocol writes its pictures through OSMesa (see ViewerWindow).
  if (!options_.final_screenshot.empty()) {
    WriteFinalScreenshot(options_.final_screenshot);
  } else if (options_.hold_at_end) {
    ShowUntilClosed();
  }
}

std::string LiveViewer::PanelText(const sim::ExperimentRunner& runner) const {
  const sim::RunRecord& record = runner.record();
  std::string text;
  char line[160];
  std::snprintf(line, sizeof(line), "%s, seed %llu\n", runner.config().name.c_str(),
                static_cast<unsigned long long>(runner.config().seed));
  text += line;
  const msgs::Pose2D truth = runner.scene().TruePose();
  std::snprintf(line, sizeof(line), "truth       x %.3f  y %.3f  th %.1f deg\n", truth.x_m,
                truth.y_m, truth.theta_rad * 180.0 / M_PI);
  text += line;
  if (!record.trajectory.empty()) {
    const sim::TrajectorySample& last = record.trajectory.back();
    for (std::size_t e = 0; e < last.estimates.size(); ++e) {
      const double error = std::hypot(last.estimates[e].x_m - last.truth.x_m,
                                      last.estimates[e].y_m - last.truth.y_m);
      std::snprintf(line, sizeof(line), "%-11s error %.3f m\n", record.estimator_names[e].c_str(),
                    error);
      text += line;
    }
  }
  const msgs::WheelSpeedCommand& wheels = runner.wheel_command();
  std::snprintf(line, sizeof(line), "wheels      %.2f / %.2f rad/s\n", wheels.left_rad_s,
                wheels.right_rad_s);
  text += line;
  std::snprintf(line, sizeof(line), "laser scans %zu, sonar rings %zu\nframes drawn %ld",
                record.laser.size(), record.sonar.size(), frames_);
  text += line;
  return text;
}

void LiveViewer::HandleRequests(int base_body_id) {
  if (controls_->TakeRecordToggle()) ToggleRecording();
  if (controls_->TakeFollowRequest()) window_->SetPreset(CameraPreset::kFollow, base_body_id);
}

void LiveViewer::ShowUntilClosed() {
  if (!window_ || !final_data_ || closed_) return;
  while (!window_->CloseRequested()) {
    window_->PollEvents();
    if (window_->Gone()) break;
    HandleRequests(base_body_id_);
    DrawFrame(final_data_.get(), final_content_, final_panel_);
    std::this_thread::sleep_for(std::chrono::milliseconds(16));
  }
  closed_ = true;
  if (video_) ToggleRecording();  // finishes the file
}

void LiveViewer::WriteFinalScreenshot(const std::filesystem::path& path) {
  if (!window_ || !final_data_)
    throw std::runtime_error(path.string() + ": the run showed nothing");
  window_->SetPreset(CameraPreset::kTopDown);
  window_->SetCapture(true);
  window_->PollEvents();
  DrawFrame(final_data_.get(), final_content_, final_panel_);
  render::WritePng(window_->Screenshot(), path);
}

void LiveViewer::ToggleRecording() {
  if (video_) {
    const std::string path = video_->path().string();
    const long frames = video_->frames();
    try {
      video_->Close();
      std::fprintf(stderr, "plywood: wrote %s (%ld frames)\n", path.c_str(), frames);
    } catch (const std::runtime_error& e) {
      std::cerr << "plywood: " << e.what() << "\n";
    }
    video_.reset();
    window_->SetCapture(false);
    return;
  }
  video_ = std::make_unique<render::VideoEncoder>(options_.video_path, kVideoFps);
  window_->SetCapture(true);
}

}  // namespace plywood::viewer
