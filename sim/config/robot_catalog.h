#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "robot/drive/diff_drive_spec.h"

namespace plywood::sim {

// A robot the testbed knows by name: its MJCF (models/) and the nominal spec its software uses.
struct RobotCatalogEntry {
  std::string name;
  std::filesystem::path mjcf;  // absolute
  robot::DiffDriveSpec nominal;
};

// "p3dx" and "magellan_pro".
const std::vector<RobotCatalogEntry>& RobotCatalog();

// @throws std::invalid_argument "unknown robot 'x' (known: p3dx, magellan_pro)".
const RobotCatalogEntry& FindRobot(const std::string& name);

// Folder with models/, worlds/ and experiments/ (the source tree the binary was built from, or
// $PLYWOOD_ROOT when set, so an installed binary can point at a copy).
// @throws std::invalid_argument naming PLYWOOD_ROOT when it is set to what is not a folder.
std::filesystem::path DataRoot();

}  // namespace plywood::sim
