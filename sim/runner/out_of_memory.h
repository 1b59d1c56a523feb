#pragma once

#include <stdexcept>
#include <string>

namespace plywood::sim {

// Memory the process could not get: MuJoCo's "Could not allocate memory" while compiling or
// making a model, a thread whose stack could not be reserved. Under `ulimit -v` these read as a
// world that "does not compile" (exit 2, bad input) or a bare "Resource temporarily unavailable";
// `what()` is "out of memory: WHAT" and names the process's memory limit when one is set. Callers
// that take a failed compile for a bad file rethrow it.
class OutOfMemory : public std::runtime_error {
 public:
  explicit OutOfMemory(const std::string& what);
};

// " (the memory limit, ulimit -v, is N kB)" when the process's address space is limited, else "".
std::string MemoryLimitNote();

// MemoryLimitNote(), and " (the process limit, ulimit -u, is N)" when a user other than root is
// held to one: what a thread or process that could not start ran into.
std::string ProcessLimitsNote();

// True when MuJoCo's message says an allocation failed ("Could not allocate mjData buffer").
bool IsMujocoOutOfMemory(const std::string& message);

}  // namespace plywood::sim
