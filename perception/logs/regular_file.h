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
// "a symbolic link to T, which does not exist" for a dangling link, the file system's reason when
// it refuses the name (a link loop, a name too long), else "not a regular file (a folder or a
// device?)" (a folder given as a log read "no such log file", though it was there).
inline std::string WhyNotARegularFile(const std::filesystem::path& path,
                                      const std::string& what = "file") {
  namespace fs = std::filesystem;
  std::error_code refused;
  const fs::file_status status = fs::status(path, refused);
  if (fs::exists(status)) return "not a regular file (a folder or a device?)";
  std::error_code ignored;
  if (fs::is_symlink(fs::symlink_status(path, ignored))) {
    if (refused && refused != std::errc::no_such_file_or_directory) return refused.message();
    return "a symbolic link to " + fs::read_symlink(path, ignored).string() +
           ", which does not exist";
  }
  if (refused && refused != std::errc::no_such_file_or_directory) return refused.message();
  return "no such " + what;
}

}  // namespace plywood::perception
