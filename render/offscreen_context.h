#pragma once

#include <memory>

namespace plywood::render {

// Whether this build links an offscreen GL backend (OSMesa; CMake option PLYWOOD_WITH_OSMESA).
inline constexpr bool kHasOffscreenRendering = PLYWOOD_HAS_OSMESA != 0;

// Whether an offscreen context can actually be created on this machine: the build must have a
// backend and the driver must hand out a context. Probed once per process.
bool OffscreenRenderingAvailable();

// Loads the offscreen backend's library (OSMesa, and with it libLLVM: ~60 ms in a fresh process)
// without making a context, so that a thread can do it while the caller builds what it will draw;
// the first context then finds it loaded. Does nothing when there is no backend or it is loaded.
void PreloadOffscreenLibrary();

// The address of the OpenGL function `name` from the offscreen backend (OSMesaGetProcAddress),
// for the few GL calls MuJoCo's mjr_* functions do not make; nullptr when there is none.
void* GlProcAddress(const char* name);

// An offscreen OpenGL context (OSMesa, software) with a `width` x `height` RGBA colour buffer,
// current on the calling thread from construction until destruction. This is the only place that
// knows the GL backend; mjr_* calls work on whatever context is current.
class OffscreenContext {
 public:
  // Creates the context and makes it current.
  // @throws std::runtime_error when the build has no backend or the driver refuses.
  OffscreenContext(int width, int height);
  ~OffscreenContext();

  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  // Makes this context current again (after another one was used on this thread).
  // @throws std::runtime_error when the driver refuses.
  void MakeCurrent();

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  struct Impl;
  int width_;
  int height_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace plywood::render
