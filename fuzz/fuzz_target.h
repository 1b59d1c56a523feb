#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace plywood::fuzz {

// One parser's harness: takes any bytes and returns normally, a clean parse error included; it
// aborts (fuzz_support.h Require) on anything the parser promises never to do.
using FuzzTarget = void (*)(std::span<const std::uint8_t> data);

// Registers `target` under `name` for the corpus replayer (replay_main.cc); returns true so that
// a static initialiser can call it.
bool RegisterFuzzTarget(const char* name, FuzzTarget target);

// The target registered under `name`, or nullptr.
FuzzTarget FindFuzzTarget(const std::string& name);

}  // namespace plywood::fuzz

// Declares a file's harness. Under libFuzzer (-DPLYWOOD_FUZZ=ON) each harness is its own binary
// with libFuzzer's entry point; in every other build all harnesses share the replayer, which runs
// the committed corpora through the very same function.
#ifdef PLYWOOD_LIBFUZZER
#define PLYWOOD_FUZZ_TARGET(name, function)                                           \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { \
    function(std::span<const std::uint8_t>(data, size));                              \
    return 0;                                                                         \
  }
#else
// One target per file: the registration lives in the file's anonymous namespace.
#define PLYWOOD_FUZZ_TARGET(name, function)                \
  namespace {                                              \
  [[maybe_unused]] const bool kFuzzTargetRegistered =      \
      ::plywood::fuzz::RegisterFuzzTarget(name, function); \
  }
#endif
