#pragma once

#include <filesystem>
#include <string>

namespace plywood::testing {

// The whole content of a file ("" if it cannot be read).
std::string Slurp(const std::filesystem::path& path);

struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Runs the built `plywood` binary with `args` (a shell-quoted string), capturing stdout and
// stderr in files under `dir`; in `working_dir` when given, else in the test's own.
CliResult RunPlywood(const std::string& args, const std::filesystem::path& dir,
                     const std::filesystem::path& working_dir = {});

}  // namespace plywood::testing
