#include "viewer/display_probe.h"

#include <GLFW/glfw3.h>

namespace plywood::viewer {
namespace {

std::string& ProbeError() {
  static std::string message;
  return message;
}

}  // namespace

std::optional<std::string> DisplayProblem() {
  ProbeError().clear();
  GLFWerrorfun previous =
      glfwSetErrorCallback([](int, const char* message) { ProbeError() = message; });
  const bool started = glfwInit() == GLFW_TRUE;
  if (started) glfwTerminate();  // the window starts GLFW again itself
  glfwSetErrorCallback(previous);
  if (started) return std::nullopt;
  return ProbeError().empty() ? std::string("GLFW could not start") : ProbeError();
}

}  // namespace plywood::viewer
