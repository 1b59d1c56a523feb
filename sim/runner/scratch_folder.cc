#include "sim/runner/scratch_folder.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

namespace plywood::sim {

std::filesystem::path ScratchFolderRoot() {
  const char* variable = std::getenv("TMPDIR");
  const std::filesystem::path root = variable != nullptr && *variable != '\0' ? variable : "/tmp";
  const auto refuse = [&](const std::string& why) {
    throw std::invalid_argument(
        "TMPDIR: " + root.string() + ": " + why +
        " (the folder plywood writes its scratch files in): point TMPDIR at a writable folder, or "
        "unset it for /tmp");
  };
  std::error_code error;
  if (!std::filesystem::is_directory(root, error)) {
    refuse(error ? error.message() : std::string("not a folder"));
  }
  // A file made and removed: a read-only file system or a folder plywood may not write in shows
  // only on a write, and access() says yes to root on both.
  const std::string probe = (root / (".plywood-probe-" + std::to_string(::getpid()))).string();
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) refuse(std::string("cannot write there: ") + std::strerror(errno));
  ::close(fd);
  ::unlink(probe.c_str());
  return root;
}

}  // namespace plywood::sim
