#include "fuzz/fuzz_support.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>

#include "fuzz/fuzz_target.h"

namespace plywood::fuzz {
namespace {

namespace fs = std::filesystem;

std::map<std::string, FuzzTarget>& Targets() {
  static std::map<std::string, FuzzTarget> targets;
  return targets;
}

std::string& CurrentInput() {
  static std::string name;
  return name;
}

// The scratch folder, removed when the process exits normally.
class Scratch {
 public:
  Scratch() {
    const char* tmp = std::getenv("TMPDIR");
    path_ = fs::path(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") /
            ("plywood-fuzz-" + std::to_string(::getpid()));
    fs::create_directories(path_);
  }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

bool RegisterFuzzTarget(const char* name, FuzzTarget target) {
  Targets()[name] = target;
  return true;
}

FuzzTarget FindFuzzTarget(const std::string& name) {
  const auto found = Targets().find(name);
  return found == Targets().end() ? nullptr : found->second;
}

std::string AsText(std::span<const std::uint8_t> data) {
  return std::string(reinterpret_cast<const char*>(data.data()), data.size());
}

fs::path ScratchFolder() {
  static const Scratch scratch;
  return scratch.path();
}

fs::path WriteScratchFile(const std::string& name, std::span<const std::uint8_t> data) {
  const fs::path path = ScratchFolder() / name;
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size()));
  file.close();
  Require(static_cast<bool>(file), "cannot write the scratch file " + path.string());
  return path;
}

void Require(bool condition, const std::string& what) {
  if (condition) return;
  std::fprintf(stderr, "fuzz: broken promise: %s\n", what.c_str());
  if (!CurrentInput().empty()) std::fprintf(stderr, "fuzz: input %s\n", CurrentInput().c_str());
  std::abort();
}

void RequireCleanError(const std::exception& error, const std::string& source) {
  const std::string message = error.what();
  Require(!message.empty(), "an empty error message");
  Require(message.find('\n') == std::string::npos, "an error of several lines: " + message);
  Require(message.find(source) != std::string::npos,
          "an error that does not name " + source + ": " + message);
  // FUZZ_REPLAY_VERBOSE=1 shows which seeds are refused (a seed should mostly load).
  if (const char* verbose = std::getenv("FUZZ_REPLAY_VERBOSE"); verbose && *verbose == '1') {
    std::fprintf(stderr, "%s: refused: %s\n", CurrentInput().c_str(), message.c_str());
  }
}

void SetCurrentInput(const std::string& name) { CurrentInput() = name; }

}  // namespace plywood::fuzz
