#include "sim/config/folder_behind_links.h"

#include <system_error>

namespace plywood::sim {

std::filesystem::path FolderBehindLinks(const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  fs::path at = fs::absolute(file);
  // The kernel's own bound on links in one lookup (a loop is left to the read that follows,
  // which names it).
  constexpr int kMaxHops = 40;
  for (int hop = 0; hop < kMaxHops; ++hop) {
    std::error_code error;
    if (!fs::is_symlink(fs::symlink_status(at, error))) break;
    const fs::path target = fs::read_symlink(at, error);
    if (error) break;
    const fs::path joined = target.is_absolute() ? target : at.parent_path() / target;
    at = joined.lexically_normal();
    // The kernel reads a ".." of the target in the folder the link really is in: where that is
    // reached through a linked folder (mine -> /data/mine, holding e.yaml -> ../lab/e.yaml), the
    // lexical climb names another folder, or none, than the one the file is read from.
    std::error_code missing;
    if (fs::exists(joined, missing) && !fs::equivalent(at, joined, missing)) {
      at = fs::canonical(joined, missing);
    }
  }
  return at.parent_path();
}

}  // namespace plywood::sim
