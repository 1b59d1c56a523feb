#pragma once

struct GLFWwindow;

namespace plywood::viewer {

// How the view's window went away other than by its close button.
enum class XLoss {
  kNone,
  kConnection,       // the X connection broke: server killed or shut down, connection killed
                     // (xkill, xdotool windowkill), an ssh -X link dropped
  kWindowDestroyed,  // another X client destroyed the window (XDestroyWindow)
};

// Where the viewed run is when the X side goes away: it decides what plywood does.
enum class ViewedRun {
  kNone,      // a replay (or nothing yet): the view ends, exit 1
  kRunning,   // the run is cut short: the view ends with it, exit 1, nothing of it written (an
              // unfinished run must not look like a result)
  kFinished,  // the run's record is complete: plywood says so in one line and goes on without
              // the window, writing every file as when the window is closed
};

// Makes the loss of the X connection end plywood with one line of its own ("plywood: view: lost
// the X display :N (...)") instead of Xlib's ("X connection to :N broken ...", then exit), and a
// window destroyed by another client ("plywood: view: the window was destroyed ...") instead of
// Xlib's raw BadWindow text. Before the run finishes: exit code 1. After: Xlib is told to return
// (XSetIOErrorExitHandler, libX11 >= 1.7) and XLossSoFar() reports the loss; the window must then
// not be used again. Xlib is found in the process (GLFW loads it), not linked; without it (no X11
// GLFW) this does nothing. After glfwInit.
void InstallXConnectionLossHandler();
// Watches `window` for destruction by another client (X errors naming it). After it is created.
void WatchXWindow(GLFWwindow* window);
void SetViewedRun(ViewedRun state);
XLoss XLossSoFar();

}  // namespace plywood::viewer
