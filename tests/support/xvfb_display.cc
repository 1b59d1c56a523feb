#include "tests/support/xvfb_display.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

extern char** environ;

namespace plywood::testing {

std::unique_ptr<XvfbDisplay> XvfbDisplay::Start(std::string* why_not) {
  int fds[2];
  if (pipe(fds) != 0) {
    *why_not = std::string("pipe: ") + std::strerror(errno);
    return nullptr;
  }
  // Xvfb writes the display number it chose, then a newline, to the -displayfd descriptor.
  std::vector<std::string> args = {"Xvfb",      "-displayfd", std::to_string(fds[1]),
                                   "-screen",   "0",          "1280x1024x24",
                                   "-nolisten", "tcp",        "-noreset"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  const int error = posix_spawnp(&pid, "Xvfb", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(fds[1]);
  if (error != 0) {
    close(fds[0]);
    *why_not = std::string("cannot start Xvfb (Debian package xvfb): ") + std::strerror(error);
    return nullptr;
  }
  std::string number;
  pollfd wait{fds[0], POLLIN, 0};
  while (number.find('\n') == std::string::npos && poll(&wait, 1, 10000) > 0) {
    char buffer[16];
    const ssize_t n = read(fds[0], buffer, sizeof(buffer));
    if (n <= 0) break;
    number.append(buffer, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  if (number.find('\n') == std::string::npos) {
    kill(pid, SIGTERM);
    waitpid(pid, nullptr, 0);
    *why_not = "Xvfb did not report a display within 10 s";
    return nullptr;
  }
  const int display = std::atoi(number.c_str());
  setenv("DISPLAY", (":" + std::to_string(display)).c_str(), 1);
  return std::unique_ptr<XvfbDisplay>(new XvfbDisplay(pid, display));
}

XvfbDisplay::~XvfbDisplay() {
  kill(pid_, SIGTERM);
  waitpid(pid_, nullptr, 0);
}

void RequireXvfbOrSkip() {
  static std::unique_ptr<XvfbDisplay> server;  // stopped when the program exits
  if (server) return;
  std::string why_not;
  server = XvfbDisplay::Start(&why_not);
  if (!server) {
    std::printf("SKIPPED: no X display for the viewer: %s\n", why_not.c_str());
    std::fflush(stdout);
    std::exit(77);
  }
}

}  // namespace plywood::testing
