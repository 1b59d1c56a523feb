#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sim/config/robot_catalog.h"
#include "sim/world/generator/generated_world.h"

namespace plywood::sim::worldgen {

// Checks a written world against what was generated, through MuJoCo: the file compiles without
// warnings; it holds the floor and exactly the generated geoms (names, shapes, poses and sizes as
// the ground truth of sim/world/ground_truth_walls.h reads them back, to 5 um); its spawn poses
// read back; and `robot` placed at each spawn pose touches nothing but the floor. Returns one
// line per defect (empty when the world is sound).
std::vector<std::string> CheckWrittenWorld(const std::filesystem::path& mjcf,
                                           const GeneratedWorld& world,
                                           const RobotCatalogEntry& robot);

}  // namespace plywood::sim::worldgen
