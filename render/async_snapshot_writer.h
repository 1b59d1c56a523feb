#pragma once

#include <mujoco/mujoco.h>

#include <condition_variable>
#include <exception>
#include <filesystem>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "render/overlay.h"
#include "render/snapshot.h"
#include "sim/world/mujoco_handles.h"

namespace plywood::render {

// WriteSnapshot on a thread of its own, started before the run it pictures: loading OSMesa and
// libLLVM, making the GL contexts, llvmpipe's shader compilation and the picture of everything
// that does not move (the model's static geoms) overlap the simulation instead of following it;
// after the run only the box round what moved is drawn (TopDownRenderer::RenderOverStaticFrame),
// and the PNG overlaps the writing of the other outputs. The PNG is WriteSnapshot's, up to a few
// pixels in the robot's box where the cut frustum rounds an edge's samples differently
// (byte-identical when the final framing is not the static one: a whole frame is drawn then).
// Errors surface in Finish.
class AsyncSnapshotWriter {
 public:
  // Copies `m` on the calling thread, so call it while nothing changes the model (not during a
  // step), then starts the thread.
  // @throws std::invalid_argument on bad options, std::runtime_error when the copy fails.
  AsyncSnapshotWriter(const mjModel* m, const SnapshotOptions& options);
  // Waits for the thread (a Write not yet drawn is dropped); errors are not reported.
  ~AsyncSnapshotWriter();
  AsyncSnapshotWriter(const AsyncSnapshotWriter&) = delete;
  AsyncSnapshotWriter& operator=(const AsyncSnapshotWriter&) = delete;

  // Hands over the picture of `d` (a state of the model given at construction, kinematics
  // computed, as after mj_step): `d` is copied here, so the caller may go on changing it. The copy
  // goes into an mjData the thread made while the run went on when that is ready
  // (HandOverDataReady), else into a new one: a new mjData page-faults in MuJoCo's whole stack
  // (10 MB for the default run; 10-45 ms after the last pose on a loaded machine), the copy into
  // the ready one takes ~0.2 ms. The picture is the same either way.
  // @pre called at most once.
  void Write(const mjData* d, std::vector<PathOverlay> paths, std::filesystem::path path);

  // Whether the thread has made the mjData the next Write copies into (for tests).
  bool HandOverDataReady();

  // Waits until the PNG is written; returns which renderer drew it.
  // @throws what WriteSnapshot would have: std::runtime_error naming the path when writing fails;
  // std::logic_error when Write was not called.
  SnapshotBackend Finish();

 private:
  struct Request {
    sim::MjDataPtr data;
    std::vector<PathOverlay> paths;
    std::filesystem::path path;
  };
  void Work();

  SnapshotOptions options_;
  sim::MjModelPtr model_;
  std::mutex mutex_;
  std::condition_variable requested_;
  std::optional<Request> request_;  // guarded by mutex_
  sim::MjDataPtr spare_data_;       // guarded by mutex_: Write's destination, made on the thread
  bool cancelled_ = false;          // guarded by mutex_
  bool written_ = false;
  SnapshotBackend backend_ = SnapshotBackend::kSoftware;
  std::exception_ptr error_;
  std::thread thread_;  // last: starts once everything above exists
};

}  // namespace plywood::render
