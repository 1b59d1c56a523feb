#include "sim/runner/scratch_folder.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
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

void RemoveScratchOfEndedProcesses(const std::filesystem::path& root, std::string_view prefix) {
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(root, error)) {
    const std::string name = entry.path().filename().string();
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
    const char* digits = name.data() + prefix.size();
    const char* end = name.data() + name.size();
    pid_t pid = 0;
    const auto [stop, parse_error] = std::from_chars(digits, end, pid);
    if (parse_error != std::errc() || stop != end || pid <= 0) continue;
    if (pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH) continue;
    struct stat status;
    if (::lstat(entry.path().c_str(), &status) != 0 || !S_ISDIR(status.st_mode) ||
        status.st_uid != ::geteuid()) {
      continue;
    }
    std::error_code ignored;
    std::filesystem::remove_all(entry.path(), ignored);
  }
}

}  // namespace plywood::sim
