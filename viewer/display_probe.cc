#include "viewer/display_probe.h"

#include <GLFW/glfw3.h>

namespace plywood::viewer {
namespace {

std::string& LastError() {
  static std::string message;
  return message;
}

}  // namespace

const std::string& LastGlfwError() { return LastError(); }

std::optional<std::string> StartGlfw() {
  LastError().clear();
  glfwSetErrorCallback([](int, const char* message) { LastError() = message; });
  if (glfwInit() == GLFW_TRUE) return std::nullopt;
  return LastError().empty() ? std::string("GLFW could not start") : LastError();
}

std::optional<std::string> DisplayProblem() {
  if (std::optional<std::string> problem = StartGlfw()) return problem;
  glfwTerminate();  // the window starts GLFW again itself
  return std::nullopt;
}

}  // namespace plywood::viewer
