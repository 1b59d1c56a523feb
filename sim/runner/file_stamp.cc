#include "sim/runner/file_stamp.h"

#include <sys/stat.h>

namespace plywood::sim {

FileStamp StampOf(const std::filesystem::path& path) {
  struct stat s {};
  if (stat(path.c_str(), &s) != 0) return {};
  return {true,
          static_cast<unsigned long long>(s.st_dev),
          static_cast<unsigned long long>(s.st_ino),
          static_cast<long long>(s.st_size),
          static_cast<long long>(s.st_mtim.tv_sec),
          static_cast<long long>(s.st_mtim.tv_nsec)};
}

}  // namespace plywood::sim
