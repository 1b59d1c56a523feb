#include "render/offscreen_context.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#if PLYWOOD_HAS_OSMESA
#include <GL/osmesa.h>
#include <dlfcn.h>
#endif

namespace plywood::render {

#if PLYWOOD_HAS_OSMESA

namespace {

// OSMesa, opened on the first snapshot rather than linked: it pulls in libLLVM, whose loading
// would otherwise add to the start of every process, snapshot or not. RTLD_GLOBAL so that
// MuJoCo's GL loader finds it among the loaded libraries, as it did when linked.
struct OsMesa {
  decltype(&OSMesaCreateContextExt) create = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaDestroyContext) destroy = nullptr;
  decltype(&OSMesaGetProcAddress) proc_address = nullptr;
};

const OsMesa& LoadOsMesa() {
  static const OsMesa loaded = [] {
    OsMesa f;
    void* library = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_GLOBAL);
    if (library == nullptr) library = dlopen("libOSMesa.so", RTLD_NOW | RTLD_GLOBAL);
    if (library == nullptr) return f;
    f.create = reinterpret_cast<decltype(f.create)>(dlsym(library, "OSMesaCreateContextExt"));
    f.make_current =
        reinterpret_cast<decltype(f.make_current)>(dlsym(library, "OSMesaMakeCurrent"));
    f.destroy = reinterpret_cast<decltype(f.destroy)>(dlsym(library, "OSMesaDestroyContext"));
    f.proc_address =
        reinterpret_cast<decltype(f.proc_address)>(dlsym(library, "OSMesaGetProcAddress"));
    if (!f.create || !f.make_current || !f.destroy || !f.proc_address) return OsMesa{};
    return f;
  }();
  return loaded;
}

}  // namespace

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
  const OsMesa& osmesa = LoadOsMesa();
  if (osmesa.create == nullptr) {
    throw std::runtime_error("OSMesa: cannot load libOSMesa.so.8");
  }
  // 24-bit depth and 8-bit stencil, as MuJoCo's renderer expects.
  impl_->context = osmesa.create(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (impl_->context == nullptr) {
    throw std::runtime_error("OSMesa: OSMesaCreateContextExt failed");
  }
  impl_->buffer.resize(static_cast<std::size_t>(width) * height * 4);
  try {
    MakeCurrent();
  } catch (...) {
    osmesa.destroy(impl_->context);
    throw;
  }
}

OffscreenContext::~OffscreenContext() {
  if (impl_ && impl_->context != nullptr) LoadOsMesa().destroy(impl_->context);
}

void OffscreenContext::MakeCurrent() {
  if (!LoadOsMesa().make_current(impl_->context, impl_->buffer.data(), GL_UNSIGNED_BYTE, width_,
                                 height_)) {
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

void PreloadOffscreenLibrary() { LoadOsMesa(); }

void* GlProcAddress(const char* name) {
  const OsMesa& osmesa = LoadOsMesa();
  return osmesa.proc_address ? reinterpret_cast<void*>(osmesa.proc_address(name)) : nullptr;
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

void PreloadOffscreenLibrary() {}

void* GlProcAddress(const char*) { return nullptr; }

#endif

}  // namespace plywood::render
