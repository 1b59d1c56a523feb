#pragma once

#include <optional>
#include <string>

namespace plywood::viewer {

// Why no window can be opened (GLFW's own words, e.g. "X11: Failed to open display :99"), or
// nullopt when GLFW starts. Asked before a view makes anything, so a DISPLAY that names no X server
// is refused as the bad environment it is rather than ending the view part way.
std::optional<std::string> DisplayProblem();

// Starts GLFW with an error callback that keeps its last message (GLFW has one global callback);
// returns that message when glfwInit fails, else nullopt. LastGlfwError() then explains a failed
// window, too.
std::optional<std::string> StartGlfw();
const std::string& LastGlfwError();

}  // namespace plywood::viewer
