#include "tests/support/mujoco_test_support.h"

#include <fstream>

#include "plywood_paths.h"

namespace plywood::testing {

std::filesystem::path SourceRoot() { return PLYWOOD_SOURCE_ROOT; }

std::filesystem::path MakeTempDir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(PLYWOOD_BINARY_DIR) / "test_tmp" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::filesystem::path WriteFile(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

}  // namespace plywood::testing
