#include "sim/config/robot_catalog.h"

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <system_error>

#include "plywood_paths.h"

namespace plywood::sim {

std::filesystem::path DataRoot() {
  const char* root = std::getenv("PLYWOOD_ROOT");
  if (root == nullptr || *root == '\0') return PLYWOOD_SOURCE_ROOT;
  // A root that is no folder read as "/missing/models/p3dx.xml: no such robot MJCF file" or
  // "world: no such file: worlds/office.xml (looked in ... and /missing)", the variable unnamed.
  std::error_code error;
  if (!std::filesystem::is_directory(root, error)) {
    throw std::invalid_argument(
        std::string("PLYWOOD_ROOT: ") + root + ": " +
        (error ? error.message() : std::string("not a folder")) +
        " (the tree plywood reads models/, worlds/ and experiments/ from): point it at a copy of "
        "the repository, or unset it");
  }
  return root;
}

const std::vector<RobotCatalogEntry>& RobotCatalog() {
  static const std::vector<RobotCatalogEntry> catalog{
      {"p3dx", DataRoot() / "models" / "p3dx.xml", robot::P3dxSpec()},
      {"magellan_pro", DataRoot() / "models" / "magellan_pro.xml", robot::MagellanProSpec()},
  };
  return catalog;
}

const RobotCatalogEntry& FindRobot(const std::string& name) {
  std::string known;
  for (const auto& entry : RobotCatalog()) {
    if (entry.name == name) return entry;
    known += (known.empty() ? "" : ", ") + entry.name;
  }
  throw std::invalid_argument("unknown robot '" + name + "' (known: " + known + ")");
}

}  // namespace plywood::sim
