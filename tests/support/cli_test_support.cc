#include "tests/support/cli_test_support.h"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "plywood_paths.h"

namespace plywood::testing {

std::string Slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
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

}  // namespace plywood::testing
