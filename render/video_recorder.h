#pragma once

#include <filesystem>
#include <memory>

#include "render/top_down_renderer.h"
#include "render/video_encoder.h"
#include "sim/runner/experiment_runner.h"
#include "sim/runner/run_observer.h"

namespace plywood::render {

struct VideoOptions {
  double fps = 10.0;         // frames per simulated second, in [1, 60]
  int longer_side_px = 640;  // frame size along the world's longer side, in [64, 4096]

  // @throws std::invalid_argument whose message starts with the offending field's name.
  void Validate() const;
};

// Records a run as an MP4 (`plywood run --video`): a RunObserver that draws a top-down frame at
// every 1 / fps of simulated time from t = 0 (offscreen through OSMesa, as snapshots are; in
// software where that is unavailable) with the paths so far, the latest laser scan, the scale bar
// and the clock, and hands it to VideoEncoder. Reads the run only: outputs stay byte-identical.
// A run of duration D gives floor(D fps) + 1 frames.
class VideoRecorder : public sim::RunObserver {
 public:
  // @throws std::invalid_argument on bad options.
  VideoRecorder(const std::filesystem::path& path, const VideoOptions& options = {});
  ~VideoRecorder() override;

  bool AfterStep(const sim::ExperimentRunner& runner) override;
  // Finishes the file. @throws std::runtime_error naming the path when ffmpeg failed.
  void RunFinished(const sim::ExperimentRunner& runner) override;

  long frames() const { return encoder_.frames(); }

 private:
  void AddFrame(const sim::ExperimentRunner& runner);

  VideoOptions options_;
  VideoEncoder encoder_;
  std::unique_ptr<TopDownRenderer> renderer_;  // null: software frames
  bool renderer_tried_ = false;
  long next_frame_ = 0;
};

}  // namespace plywood::render
