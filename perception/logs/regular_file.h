#pragma once

#include <filesystem>
#include <system_error>

namespace plywood::perception {

// Whether `path` names a regular file. A name the file system refuses (too long, a component over
// 255 bytes) is not a file here, where std::filesystem::is_regular_file(path) would throw a
// filesystem_error past every reader's one-line errors (found by fuzzing the experiment YAML).
inline bool IsRegularFile(const std::filesystem::path& path) {
  std::error_code refused;
  return std::filesystem::is_regular_file(path, refused);
}

}  // namespace plywood::perception
