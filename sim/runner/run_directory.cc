#include "sim/runner/run_directory.h"

#include <fstream>
#include <string>

#include "sim/config/config_error.h"

namespace plywood::sim {

bool HoldsPlywoodRun(const std::filesystem::path& dir) {
  std::ifstream config(dir / "config.yaml");
  std::string first_line;
  return config && std::getline(config, first_line) && first_line.starts_with("name: ");
}

void PrepareRunDirectory(const std::filesystem::path& dir, bool force) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(dir, error);
  if (!fs::exists(status)) return;
  if (!fs::is_directory(status)) {
    throw ConfigError(dir.string(), "", "exists and is not a directory; choose another --out");
  }
  if (fs::is_empty(dir)) return;
  if (!HoldsPlywoodRun(dir)) {
    throw ConfigError(dir.string(), "",
                      "holds files that are not a Plywood run (no config.yaml); choose another "
                      "--out (--force never deletes them)");
  }
  if (!force) {
    throw ConfigError(dir.string(), "",
                      "already holds an earlier run; add --force to replace it, or choose another "
                      "--out");
  }
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    fs::remove_all(entry.path());
  }
}

}  // namespace plywood::sim
