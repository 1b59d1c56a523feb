#include "sim/config/robot_catalog.h"

#include <cstdlib>
#include <stdexcept>

#include "plywood_paths.h"

namespace plywood::sim {

std::filesystem::path DataRoot() {
  if (const char* root = std::getenv("PLYWOOD_ROOT"); root != nullptr && *root != '\0') return root;
  return PLYWOOD_SOURCE_ROOT;
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
