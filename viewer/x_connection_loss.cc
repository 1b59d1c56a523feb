#include "viewer/x_connection_loss.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace plywood::viewer {
namespace {

// Xlib's types, without its header: only pointers pass through.
using XDisplay = void;
using IoErrorHandler = int (*)(XDisplay*);
using SetIoErrorHandler = IoErrorHandler (*)(IoErrorHandler);
using DisplayName = char* (*)(XDisplay*);

DisplayName display_name = nullptr;

int OnConnectionLost(XDisplay* display) {
  const char* name = display != nullptr && display_name != nullptr ? display_name(display) : "";
  std::fflush(stdout);
  std::fprintf(stderr,
               "plywood: view: lost the X display %s (its X server was killed or shut down); the "
               "view ends here, and a live run with it, unfinished\n",
               name != nullptr ? name : "");
  std::fflush(stderr);
  // Xlib may not be called again, nor may this return (Xlib would exit without a word); exit()'s
  // destructors would close the window through the dead connection.
  _exit(1);
}

}  // namespace

void InstallXConnectionLossHandler() {
  const auto set = reinterpret_cast<SetIoErrorHandler>(dlsym(RTLD_DEFAULT, "XSetIOErrorHandler"));
  if (set == nullptr) return;
  display_name = reinterpret_cast<DisplayName>(dlsym(RTLD_DEFAULT, "XDisplayString"));
  set(&OnConnectionLost);
}

}  // namespace plywood::viewer
