#include "viewer/gl_driver_pin.h"

#include <dlfcn.h>
#include <link.h>

#include <string_view>

namespace plywood::viewer {

std::vector<std::string> LoadedGlDrivers() {
  std::vector<std::string> drivers;
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* out) {
        const std::string_view path = info->dlpi_name != nullptr ? info->dlpi_name : "";
        if (path.ends_with("_dri.so"))
          static_cast<std::vector<std::string>*>(out)->emplace_back(path);
        return 0;
      },
      &drivers);
  return drivers;
}

int PinLoadedGlDrivers() {
  int pinned = 0;
  for (const std::string& path : LoadedGlDrivers()) {
    // RTLD_NOLOAD: only a module already loaded; RTLD_NODELETE then stays with it, so the
    // display's dlclose no longer unloads it. Our own reference is dropped again at once.
    if (void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE)) {
      dlclose(handle);
      ++pinned;
    }
  }
  return pinned;
}

}  // namespace plywood::viewer
