#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "sim/runner/experiment_runner.h"
#include "sim/runner/run_observer.h"
#include "sim/world/mujoco_handles.h"
#include "viewer/run_content.h"
#include "viewer/view_controls.h"
#include "viewer/viewer_window.h"

namespace plywood::render {
class VideoEncoder;
}

namespace plywood::viewer {

struct LiveViewerOptions {
  WindowOptions window;
  TeleopOptions teleop;
  bool start_paused = false;
  Speed speed = Speed::kRealTime;
  // Frames drawn per wall-clock second at most; 0: one at every chance (the --bench figure).
  double max_fps = 60.0;
  // Where the V key records the window to (docs: an MP4 beside the user's work, never in the run
  // directory, whose file list is fixed).
  std::string video_path = "plywood-view.mp4";
  // When the run ends: write the final frame (top-down) to this PNG (empty: none); otherwise,
  // with hold_at_end, keep showing the final state until the window is closed. Both happen before
  // the run's outputs are written (see ViewerWindow on OSMesa).
  std::string final_screenshot;
  bool hold_at_end = true;

  // @throws std::invalid_argument whose message starts with the offending field's name.
  void Validate() const;
};

// The interactive viewer of a live run: a RunObserver the runner calls after every step. It paces
// the run (1x, 10x, unlimited, paused, single step), draws the world and the overlays at up to
// max_fps, and lends the wheels to the keyboard while teleoperating. The window opens at the
// first step (the runner owns the model).
class LiveViewer : public sim::RunObserver {
 public:
  explicit LiveViewer(const LiveViewerOptions& options = {});
  ~LiveViewer() override;

  bool AfterStep(const sim::ExperimentRunner& runner) override;
  std::optional<msgs::WheelSpeedCommand> WheelOverride() override;
  // Keeps the final state, then writes final_screenshot or holds the window (options).
  void RunFinished(const sim::ExperimentRunner& runner) override;

  // Opens the window now (AfterStep does it at the first step otherwise).
  // @throws std::runtime_error when no window can be opened.
  void Open(const sim::ExperimentRunner& runner);
  // Draws the runner's current state now.
  void Draw(const sim::ExperimentRunner& runner);
  // After the run: the final state top-down, written as PNG.
  // @throws std::runtime_error naming `path` when writing fails.
  void WriteFinalScreenshot(const std::filesystem::path& path);

  ViewControls& controls() { return *controls_; }
  ViewerWindow& window() { return *window_; }
  bool closed() const { return closed_; }
  long frames_drawn() const { return frames_; }

 private:
  using Clock = std::chrono::steady_clock;
  void ToggleRecording();
  void HandleRequests(int base_body_id);
  void ShowUntilClosed();
  void DrawFrame(mjData* d, const FrameContent& content, const std::string& panel);
  std::string PanelText(const sim::ExperimentRunner& runner) const;

  LiveViewerOptions options_;
  std::unique_ptr<ViewerWindow> window_;
  std::unique_ptr<ViewControls> controls_;
  std::unique_ptr<RunContent> content_;
  std::unique_ptr<render::VideoEncoder> video_;
  // The final state, kept by RunFinished.
  sim::MjDataPtr final_data_;
  FrameContent final_content_;
  std::string final_panel_;
  int base_body_id_ = 0;
  render::WorldBounds world_;
  bool closed_ = false;
  long frames_ = 0;
  Clock::time_point last_frame_end_;
  double last_frame_cost_s_ = 0.0;
  // Pacing anchor: the simulated time and wall time when the speed last changed or a pause ended.
  Clock::time_point anchor_wall_;
  double anchor_sim_s_ = 0.0;
  double anchor_factor_ = -1.0;
  Clock::time_point start_wall_;
  double start_sim_s_ = 0.0;
};

}  // namespace plywood::viewer
