#include "viewer/x_connection_loss.h"

#include <dlfcn.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace plywood::viewer {
namespace {

// Xlib's types, without its header: only pointers pass through, but for XErrorEvent, whose layout
// is the X11 ABI.
using XDisplay = void;
struct XErrorEventAbi {
  int type;
  XDisplay* display;
  unsigned long resourceid;
  unsigned long serial;
  unsigned char error_code;
  unsigned char request_code;
  unsigned char minor_code;
};
constexpr unsigned char kBadWindow = 3;
constexpr unsigned char kBadDrawable = 9;
using IoErrorHandler = int (*)(XDisplay*);
using SetIoErrorHandler = IoErrorHandler (*)(IoErrorHandler);
using IoErrorExitHandler = void (*)(XDisplay*, void*);
using SetIoErrorExitHandler = void (*)(XDisplay*, IoErrorExitHandler, void*);
using ErrorHandler = int (*)(XDisplay*, XErrorEventAbi*);
using SetErrorHandler = ErrorHandler (*)(ErrorHandler);
using DisplayName = char* (*)(XDisplay*);
using GlfwX11Display = XDisplay* (*)();
using GlfwX11Window = unsigned long (*)(GLFWwindow*);

DisplayName display_name = nullptr;
// Whether Xlib can be told to return after a lost connection (libX11 >= 1.7).
bool can_survive = false;
ErrorHandler previous_error_handler = nullptr;
unsigned long watched_window = 0;
std::atomic<ViewedRun> viewed_run{ViewedRun::kNone};
std::atomic<XLoss> loss{XLoss::kNone};

const char* Consequence(ViewedRun run) {
  switch (run) {
    case ViewedRun::kNone:
      return "the view ends here";
    case ViewedRun::kRunning:
      return "the view ends here, and the live run with it, unfinished: nothing of it is written";
    case ViewedRun::kFinished:
      return "the run had finished: its files are written as when the window is closed";
  }
  return "";
}

// Prints one line; unless the run had finished (and Xlib can go on), ends plywood with exit 1.
// Xlib may not be called again after a lost connection, nor may its handler return unless told
// (Xlib would exit without a word); exit()'s destructors would close the window through it.
void Report(XLoss what, const char* display) {
  const ViewedRun run = viewed_run.load();
  const bool goes_on = run == ViewedRun::kFinished && (what != XLoss::kConnection || can_survive);
  if (loss.exchange(what) != XLoss::kNone && goes_on) return;  // said once
  std::fflush(stdout);
  if (what == XLoss::kConnection) {
    std::fprintf(stderr,
                 "plywood: view: lost the X display %s (its X server or the connection to it went "
                 "away); %s\n",
                 display,
                 goes_on || run != ViewedRun::kFinished
                     ? Consequence(run)
                     : "the run had finished, but this libX11 (< 1.7) cannot go on without its "
                       "display: nothing of it is written");
  } else {
    std::fprintf(stderr, "plywood: view: the window was destroyed by another X client; %s\n",
                 Consequence(run));
  }
  std::fflush(stderr);
  if (!goes_on) _exit(1);
}

int OnConnectionLost(XDisplay* display) {
  const char* name = display != nullptr && display_name != nullptr ? display_name(display) : "";
  Report(XLoss::kConnection, name != nullptr ? name : "");
  return 0;
}

// Called by Xlib after OnConnectionLost returned; returning (instead of exiting) makes Xlib's
// calls on the display fail from now on.
void OnConnectionLostExit(XDisplay*, void*) {}

int OnXError(XDisplay* display, XErrorEventAbi* event) {
  // Once gone, every error naming the window follows from it (GLX's own codes too).
  if (watched_window != 0 && event->resourceid == watched_window &&
      (event->error_code == kBadWindow || event->error_code == kBadDrawable ||
       loss.load() != XLoss::kNone)) {
    Report(XLoss::kWindowDestroyed, "");
    return 0;
  }
  return previous_error_handler != nullptr ? previous_error_handler(display, event) : 0;
}

template <typename F>
F Find(const char* name) {
  return reinterpret_cast<F>(dlsym(RTLD_DEFAULT, name));
}

}  // namespace

void InstallXConnectionLossHandler() {
  const auto set = Find<SetIoErrorHandler>("XSetIOErrorHandler");
  if (set == nullptr) return;
  display_name = Find<DisplayName>("XDisplayString");
  set(&OnConnectionLost);
  const auto set_exit = Find<SetIoErrorExitHandler>("XSetIOErrorExitHandler");
  const auto glfw_display = Find<GlfwX11Display>("glfwGetX11Display");
  XDisplay* display = glfw_display != nullptr ? glfw_display() : nullptr;
  if (set_exit != nullptr && display != nullptr) {
    set_exit(display, &OnConnectionLostExit, nullptr);
    can_survive = true;
  }
}

void WatchXWindow(GLFWwindow* window) {
  const auto set = Find<SetErrorHandler>("XSetErrorHandler");
  const auto glfw_window = Find<GlfwX11Window>("glfwGetX11Window");
  if (set == nullptr || glfw_window == nullptr || window == nullptr) return;
  watched_window = glfw_window(window);
  if (watched_window == 0) return;
  const ErrorHandler previous = set(&OnXError);
  if (previous != &OnXError) previous_error_handler = previous;
}

void SetViewedRun(ViewedRun state) { viewed_run = state; }

XLoss XLossSoFar() { return loss.load(); }

}  // namespace plywood::viewer
