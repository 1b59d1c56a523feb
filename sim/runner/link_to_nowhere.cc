#include "sim/runner/link_to_nowhere.h"

#include <system_error>

namespace plywood::sim {

std::optional<std::string> LinkToNowhere(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::exists(fs::status(path, error)) || !fs::is_symlink(fs::symlink_status(path, error))) {
    return std::nullopt;
  }
  return "is a symbolic link to " + fs::read_symlink(path, error).string() +
         ", which does not exist (or links round in a loop)";
}

}  // namespace plywood::sim
