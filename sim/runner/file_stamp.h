#pragma once

#include <filesystem>

namespace plywood::sim {

// What is at a path at one moment: nothing, or a file of this inode, size and modification time.
// Taken when a long command starts and again before it renames its output into place, it tells
// whether another process wrote the output meanwhile (two trainings into one --out), which the
// rename would silently replace while both exit 0.
struct FileStamp {
  bool exists = false;
  unsigned long long device = 0, inode = 0;
  long long size = 0, modified_s = 0, modified_ns = 0;

  bool operator==(const FileStamp&) const = default;
};

// The stamp of `path` (followed through links); "nothing there" when it cannot be looked at.
FileStamp StampOf(const std::filesystem::path& path);

}  // namespace plywood::sim
