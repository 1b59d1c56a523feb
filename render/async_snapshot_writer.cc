#include "render/async_snapshot_writer.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "render/png_image.h"
#include "render/top_down_renderer.h"
#include "sim/runner/start_thread.h"

namespace plywood::render {

AsyncSnapshotWriter::AsyncSnapshotWriter(const mjModel* m, const SnapshotOptions& options)
    : options_(options) {
  options_.Validate();
  model_.reset(mj_copyModel(nullptr, m));
  if (!model_) throw std::runtime_error("snapshot: mj_copyModel failed");
  thread_ = sim::StartThread("draw the snapshot", [this] { Work(); });
}

AsyncSnapshotWriter::~AsyncSnapshotWriter() {
  {
    std::lock_guard lock(mutex_);
    cancelled_ = true;
  }
  requested_.notify_one();
  if (thread_.joinable()) thread_.join();
}

void AsyncSnapshotWriter::Write(const mjData* d, std::vector<PathOverlay> paths,
                                std::filesystem::path path) {
  sim::MjDataPtr spare;
  {
    std::lock_guard lock(mutex_);
    if (written_) throw std::logic_error("AsyncSnapshotWriter::Write: called twice");
    spare = std::move(spare_data_);
  }
  // Into the thread's spare data when it is ready (its pages already touched), else a new copy.
  Request request{sim::MjDataPtr(mj_copyData(spare.release(), model_.get(), d)), std::move(paths),
                  std::move(path)};
  if (!request.data) throw std::runtime_error("snapshot: mj_copyData failed");
  {
    std::lock_guard lock(mutex_);
    written_ = true;
    request_ = std::move(request);
  }
  requested_.notify_one();
}

bool AsyncSnapshotWriter::HandOverDataReady() {
  std::lock_guard lock(mutex_);
  return spare_data_ != nullptr;
}

SnapshotBackend AsyncSnapshotWriter::Finish() {
  {
    std::lock_guard lock(mutex_);
    if (!written_) throw std::logic_error("AsyncSnapshotWriter::Finish: Write was not called");
  }
  if (thread_.joinable()) thread_.join();
  if (error_) std::rethrow_exception(error_);
  return backend_;
}

void AsyncSnapshotWriter::Work() {
  try {
    // Write's destination, made first (a few ms): Write comes at the end of the run, or at once
    // when the writer is made after it (then there is nothing to make).
    bool spare_wanted = false;
    {
      std::lock_guard lock(mutex_);
      spare_wanted = !written_;
    }
    if (sim::MjDataPtr spare(spare_wanted ? mj_makeData(model_.get()) : nullptr); spare) {
      std::lock_guard lock(mutex_);
      if (!written_) spare_data_ = std::move(spare);
    }
    // Everything GL lives and dies on this thread, where its context is current.
    std::unique_ptr<TopDownRenderer> renderer;
    std::string why_software;
    if (options_.use_opengl) {
      // No OffscreenRenderingAvailable() probe first: it makes and destroys a context of its own
      // (~75M instructions); the renderer's context fails the same way when there is none.
      try {
        const WorldBounds static_bounds = SnapshotBounds(model_.get(), {}, options_);
        renderer = std::make_unique<TopDownRenderer>(model_.get(), static_bounds, options_.view);
        // The model's initial state drawn once, so that llvmpipe compiles its shaders now
        // rather than after the run.
        const sim::MjDataPtr initial(mj_makeData(model_.get()));
        if (!initial) throw std::runtime_error("offscreen rendering: mj_makeData failed");
        // Poses only: what the scene is built from (no contacts, no dynamics).
        mj_kinematics(model_.get(), initial.get());
        mj_comPos(model_.get(), initial.get());
        mj_camlight(model_.get(), initial.get());
        // Everything that does not move, drawn while the run goes on: after it only the box
        // round the robot is drawn anew (docs/performance.md, "Stop 67").
        renderer->KeepStaticFrame(initial.get());
      } catch (const std::runtime_error& e) {
        renderer.reset();
        // Without any context the probe's reason, as WriteSnapshot gives it.
        why_software = WhyNoOpenGl(options_);
        if (why_software.empty()) why_software = e.what();
      }
    }
    std::unique_lock lock(mutex_);
    requested_.wait(lock, [this] { return request_.has_value() || cancelled_; });
    if (!request_) return;
    Request request = std::move(*request_);
    lock.unlock();

    const WorldBounds bounds = SnapshotBounds(model_.get(), request.paths, options_);
    Snapshot snapshot;
    bool drawn = false;
    if (renderer) {
      try {
        // The buffers were sized for the static geometry's picture; paths beyond it can need
        // bigger ones (a new context, compiled afresh).
        if (!renderer->Reframe(bounds)) {
          renderer.reset();
          renderer = std::make_unique<TopDownRenderer>(model_.get(), bounds, options_.view);
        }
        snapshot = {renderer->RenderOverStaticFrame(request.data.get()), SnapshotBackend::kOpenGl};
        drawn = true;
      } catch (const std::runtime_error& e) {
        why_software = e.what();
      }
      renderer.reset();  // frees the GL context before the overlays and the PNG
    }
    if (!drawn) {
      snapshot = SoftwareSnapshot(model_.get(), request.data.get(), bounds, options_, why_software);
    }
    DrawSnapshotOverlays(&snapshot, request.paths, options_);
    WritePng(snapshot.picture.image, request.path);
    backend_ = snapshot.backend;
  } catch (...) {
    error_ = std::current_exception();
  }
}

}  // namespace plywood::render
