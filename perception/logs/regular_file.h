#pragma once

#include <filesystem>
#include <string>
#include <system_error>

namespace plywood::perception {

// Whether `path` names a regular file. A name the file system refuses (too long, a component over
// 255 bytes) is not a file here, where std::filesystem::is_regular_file(path) would throw a
// filesystem_error past every reader's one-line errors (found by fuzzing the experiment YAML).
inline bool IsRegularFile(const std::filesystem::path& path) {
  std::error_code refused;
  return std::filesystem::is_regular_file(path, refused);
}

// Why `path` is not a regular file, for a one-line error: "no such <what>" when nothing is there,
// else "not a regular file (a folder or a device?)" (a folder given as a log read "no such log
// file", though it was there).
inline std::string WhyNotARegularFile(const std::filesystem::path& path,
                                      const std::string& what = "file") {
  std::error_code refused;
  return std::filesystem::exists(path, refused) ? "not a regular file (a folder or a device?)"
                                                : "no such " + what;
}

}  // namespace plywood::perception
