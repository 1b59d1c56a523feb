#pragma once

#include <optional>
#include <string>

namespace plywood::viewer {

// Why no window can be opened (GLFW's own words, e.g. "X11: Failed to open display :99"), or
// nullopt when GLFW starts. Asked before a view makes anything, so a DISPLAY that names no X server
// is refused as the bad environment it is rather than ending the view part way.
std::optional<std::string> DisplayProblem();

}  // namespace plywood::viewer
