#include "tests/support/cli_test_support.h"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "plywood_paths.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::testing {

std::string Slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

bool PythonImports(const std::string& modules) {
  const std::string code = modules.empty() ? "" : "import " + modules;
  return std::system(("/usr/bin/python3 -c '" + code + "' >/dev/null 2>&1").c_str()) == 0;
}

CliResult RunScript(const std::filesystem::path& dir, const std::string& script,
                    const std::string& args, const std::string& prefix) {
  const std::string command = "cd '" + dir.string() + "' && " + prefix + " '" +
                              (SourceRoot() / "scripts" / script).string() + "' " + args +
                              " >stdout 2>stderr";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, Slurp(dir / "stdout"),
          Slurp(dir / "stderr")};
}

CliResult RunPlywood(const std::string& args, const std::filesystem::path& dir,
                     const std::filesystem::path& working_dir) {
  const std::filesystem::path binary =
      std::filesystem::path(PLYWOOD_BINARY_DIR) / "apps" / "plywood";
  const std::string cd = working_dir.empty() ? "" : "cd '" + working_dir.string() + "' && ";
  const std::string command = cd + binary.string() + " " + args + " >" + (dir / "stdout").string() +
                              " 2>" + (dir / "stderr").string();
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, Slurp(dir / "stdout"),
          Slurp(dir / "stderr")};
}

CliResult RunPlywoodIntoAPipe(const std::string& args) {
  const std::string command =
      (std::filesystem::path(PLYWOOD_BINARY_DIR) / "apps" / "plywood").string() + " " + args +
      " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return {};
  CliResult result;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) {
    result.out.append(buffer, n);
  }
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace plywood::testing
