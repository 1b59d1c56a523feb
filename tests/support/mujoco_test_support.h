#pragma once

#include <filesystem>
#include <string>

namespace plywood::testing {

// Root of the source tree (models/, worlds/, experiments/).
std::filesystem::path SourceRoot();

// A fresh empty directory under the build tree for one test's files.
std::filesystem::path MakeTempDir(const std::string& name);

// Writes `text` to `path` (creating folders) and returns the path.
std::filesystem::path WriteFile(const std::filesystem::path& path, const std::string& text);

}  // namespace plywood::testing
