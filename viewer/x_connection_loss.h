#pragma once

namespace plywood::viewer {

// Makes the loss of the X connection (the X server killed or shut down mid-view) end plywood with
// one line of its own, "plywood: view: lost the X display :N (...)", and exit code 1. Xlib's own
// handler printed "X connection to :N broken (explicit kill or server shutdown)." and exited,
// naming neither plywood nor what was lost. Xlib is found in the process (GLFW loads it), not
// linked; without it (no X11 GLFW) this does nothing.
void InstallXConnectionLossHandler();

}  // namespace plywood::viewer
