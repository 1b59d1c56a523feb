#pragma once

#include <filesystem>

namespace plywood::sim {

// An exclusive flock on a folder itself (no lock file left in it), held until destroyed, released
// when the process ends however it ends. For commands that write a set of files into a folder the
// user names (`worlds generate --out`): a second one beside the first is told so instead of mixing
// its files with the first's.
class FolderLock {
 public:
  // Tries once, without waiting. A folder that cannot be opened, or a file system without flock,
  // is not locked and not busy: the command runs as it did before.
  explicit FolderLock(const std::filesystem::path& folder);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  // Whether another process holds the folder's lock (this one then holds nothing).
  bool busy() const { return busy_; }

 private:
  int fd_ = -1;
  bool busy_ = false;
};

}  // namespace plywood::sim
