#include "apps/standard_streams.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <initializer_list>

namespace plywood::apps {
namespace {

void OpenOnDevNullIfClosed(int fd) {
  if (fcntl(fd, F_GETFD) != -1 || errno != EBADF) return;
  const int opened = open("/dev/null", fd == STDIN_FILENO ? O_RDONLY : O_WRONLY);
  if (opened < 0 || opened == fd) return;  // the lowest free number: fd, as 0..fd-1 are open
  dup2(opened, fd);
  close(opened);
}

// A pipe or socket whose reader has gone: poll() reports an error or hang-up on the writing end.
bool ReaderHasGone(int fd) {
  pollfd watched{fd, POLLOUT, 0};
  return poll(&watched, 1, 0) == 1 && (watched.revents & (POLLERR | POLLHUP)) != 0;
}

}  // namespace

void PrepareStandardStreams() {
  for (const int fd : {STDIN_FILENO, STDOUT_FILENO, STDERR_FILENO}) OpenOnDevNullIfClosed(fd);
  std::signal(SIGPIPE, SIG_IGN);
}

int FinishStandardStreams(int exit_code) {
  bool failed = std::ferror(stdout) != 0;
  errno = 0;
  if (std::fflush(stdout) != 0) failed = true;
  const int reason = errno;
  if ((failed && ReaderHasGone(STDOUT_FILENO)) ||
      (std::ferror(stderr) != 0 && ReaderHasGone(STDERR_FILENO))) {
    std::signal(SIGPIPE, SIG_DFL);
    std::raise(SIGPIPE);
  }
  if (!failed) return exit_code;
  std::fprintf(stderr, "plywood: error: stdout: write failed%s%s\n", reason != 0 ? ": " : "",
               reason != 0 ? std::strerror(reason) : "");
  return exit_code == 0 ? 1 : exit_code;
}

}  // namespace plywood::apps
