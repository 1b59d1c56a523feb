// In a process of its own: whether OSMesa is loaded is process-wide, and any other test that
// draws would have loaded it first.

#include <dlfcn.h>
#include <gtest/gtest.h>

#include "render/offscreen_context.h"

namespace plywood::render {
namespace {

bool OsMesaLoaded() {
  void* library = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_NOLOAD);
  if (library == nullptr) return false;
  dlclose(library);  // NOLOAD took a reference
  return true;
}

TEST(OffscreenLibraryPreloadTest, LoadsTheLibraryWithoutAContextAndAContextWorksAfter) {
  if (!kHasOffscreenRendering) GTEST_SKIP() << "built without OSMesa";
  ASSERT_FALSE(OsMesaLoaded()) << "OSMesa is loaded at process start: nothing to preload";
  PreloadOffscreenLibrary();
  const bool loaded_by_the_preload = OsMesaLoaded();
  // A context made after the preload, from the library it loaded.
  if (!OffscreenRenderingAvailable()) GTEST_SKIP() << "no offscreen OpenGL context here";
  EXPECT_TRUE(loaded_by_the_preload);
}

}  // namespace
}  // namespace plywood::render
