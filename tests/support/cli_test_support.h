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

// Whether Debian's /usr/bin/python3 is there and imports `modules` (comma-separated, "" for none):
// the scripts' tests skip, saying so, where it does not.
bool PythonImports(const std::string& modules = "");

// Runs `[prefix] scripts/SCRIPT args` of the source tree in `dir` (prefix: an interpreter and its
// flags, "/usr/bin/python3 -S"; args shell-quoted), stdout and stderr into files there.
CliResult RunScript(const std::filesystem::path& dir, const std::string& script,
                    const std::string& args, const std::string& prefix = "");

// Runs the built `plywood` binary with `args` (a shell-quoted string), capturing stdout and
// stderr in files under `dir`; in `working_dir` when given, else in the test's own.
CliResult RunPlywood(const std::string& args, const std::filesystem::path& dir,
                     const std::filesystem::path& working_dir = {});

// Runs the built `plywood` binary with `args`, its stdout and stderr both into a pipe the test
// reads (as `plywood ... | jq` would): `out` holds both, `err` is empty.
CliResult RunPlywoodIntoAPipe(const std::string& args);

}  // namespace plywood::testing
