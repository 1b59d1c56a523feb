#include "render/offscreen_context.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#if PLYWOOD_HAS_OSMESA
#include <GL/osmesa.h>
#endif

namespace plywood::render {

#if PLYWOOD_HAS_OSMESA

struct OffscreenContext::Impl {
  OSMesaContext context = nullptr;
  std::vector<std::uint8_t> buffer;  // RGBA, owned here because OSMesa renders into it
};

OffscreenContext::OffscreenContext(int width, int height)
    : width_(width), height_(height), impl_(std::make_unique<Impl>()) {
  if (width <= 0 || height <= 0) {
    throw std::invalid_argument("width, height: must be > 0, got " + std::to_string(width) + " x " +
                                std::to_string(height));
  }
  // 24-bit depth and 8-bit stencil, as MuJoCo's renderer expects.
  impl_->context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (impl_->context == nullptr) {
    throw std::runtime_error("OSMesa: OSMesaCreateContextExt failed");
  }
  impl_->buffer.resize(static_cast<std::size_t>(width) * height * 4);
  try {
    MakeCurrent();
  } catch (...) {
    OSMesaDestroyContext(impl_->context);
    throw;
  }
}

OffscreenContext::~OffscreenContext() {
  if (impl_ && impl_->context != nullptr) OSMesaDestroyContext(impl_->context);
}

void OffscreenContext::MakeCurrent() {
  if (!OSMesaMakeCurrent(impl_->context, impl_->buffer.data(), GL_UNSIGNED_BYTE, width_, height_)) {
    throw std::runtime_error("OSMesa: OSMesaMakeCurrent failed");
  }
}

bool OffscreenRenderingAvailable() {
  static const bool available = [] {
    try {
      OffscreenContext probe(4, 4);
      return true;
    } catch (const std::exception&) {
      return false;
    }
  }();
  return available;
}

#else  // !PLYWOOD_HAS_OSMESA

struct OffscreenContext::Impl {};

OffscreenContext::OffscreenContext(int width, int height) : width_(width), height_(height) {
  throw std::runtime_error(
      "offscreen rendering: this build has no OSMesa (PLYWOOD_WITH_OSMESA=OFF)");
}

OffscreenContext::~OffscreenContext() = default;

void OffscreenContext::MakeCurrent() {
  throw std::runtime_error("offscreen rendering: this build has no OSMesa");
}

bool OffscreenRenderingAvailable() { return false; }

#endif

}  // namespace plywood::render
