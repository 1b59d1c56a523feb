#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace plywood::sim {

// When `path` is a symbolic link whose target does not exist (or whose links run round in a
// loop): "is a symbolic link to TARGET, which does not exist (or links round in a loop)", for the
// line that refuses it as an output folder. Making the folder through it read "File exists" or
// "Too many levels of symbolic links", which named neither the link nor its target.
std::optional<std::string> LinkToNowhere(const std::filesystem::path& path);

}  // namespace plywood::sim
