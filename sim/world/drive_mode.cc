#include "sim/world/drive_mode.h"

#include <stdexcept>

namespace plywood::sim {

std::string ToString(DriveMode mode) { return mode == DriveMode::kPlanar ? "planar" : "contact"; }

DriveMode ParseDriveMode(const std::string& text) {
  if (text == "contact") return DriveMode::kContact;
  if (text == "planar") return DriveMode::kPlanar;
  throw std::invalid_argument("expected contact or planar, got '" + text + "'");
}

}  // namespace plywood::sim
