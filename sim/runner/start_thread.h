#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <utility>

#include "sim/runner/out_of_memory.h"

namespace plywood::sim {

// A thread running `work`. Its stack could not be reserved under a memory limit (`ulimit -v`), nor
// the thread made under a process limit (`ulimit -u`), and std::thread's error read "plywood:
// error: Resource temporarily unavailable", naming neither the thread nor the limit.
// @throws std::runtime_error "cannot start a thread to PURPOSE: REASON (the memory limit ...)".
inline std::thread StartThread(const std::string& purpose, std::function<void()> work) {
  try {
    return std::thread(std::move(work));
  } catch (const std::system_error& e) {
    throw std::runtime_error("cannot start a thread to " + purpose + ": " + e.code().message() +
                             ProcessLimitsNote());
  }
}

}  // namespace plywood::sim
