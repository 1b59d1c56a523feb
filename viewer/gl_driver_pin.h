#pragma once

#include <string>
#include <vector>

namespace plywood::viewer {

// Paths of the Mesa DRI drivers (`*_dri.so`: swrast_dri.so under Xvfb) loaded in this process.
std::vector<std::string> LoadedGlDrivers();

// Keeps every loaded DRI driver in memory until the process exits. Mesa's GLX unloads its driver
// when GLFW closes the display (glfwTerminate), and with it the driver's globals that still point
// at blocks it allocated: each unload loses them for good (~0.2 kB), and LeakSanitizer reports
// them with frames of `<unknown module>` that no suppression by library name can match. Pinned,
// the driver's globals stay mapped, the blocks stay reachable, and the sanitizer build needs no
// suppression for it. A second window in the same process also reuses the loaded driver instead
// of loading it (and LLVM) again.
// @returns how many drivers were pinned (0 when no window's GL context is open).
int PinLoadedGlDrivers();

}  // namespace plywood::viewer
