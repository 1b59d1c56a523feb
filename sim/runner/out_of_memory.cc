#include "sim/runner/out_of_memory.h"

#include <sys/resource.h>
#include <unistd.h>

namespace plywood::sim {

OutOfMemory::OutOfMemory(const std::string& what)
    : std::runtime_error("out of memory: " + what + MemoryLimitNote()) {}

std::string MemoryLimitNote() {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return "";
  return " (the memory limit, ulimit -v, is " + std::to_string(limit.rlim_cur / 1024) + " kB)";
}

std::string ProcessLimitsNote() {
  rlimit limit{};
  if (getrlimit(RLIMIT_NPROC, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY || geteuid() == 0) {
    return MemoryLimitNote();
  }
  return MemoryLimitNote() + " (the process limit, ulimit -u, is " +
         std::to_string(limit.rlim_cur) + ")";
}

bool IsMujocoOutOfMemory(const std::string& message) {
  // "Could not allocate memory", "Could not allocate mjData buffer", "mjFileToMemory: could not
  // allocate memory", ...
  return message.find("ould not allocate") != std::string::npos;
}

}  // namespace plywood::sim
