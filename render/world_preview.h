#pragma once

#include <filesystem>

namespace plywood::render {

// A top-down picture of a world file for a person to look at: the static geometry as the
// snapshots draw it (render/snapshot.h) with the walls (geoms named wall_N) traced 2 px wide so
// they show at any scale, and at each spawn pose the disc `robot_reach_m` around
// it (the footprint a spawn must leave free) with an arrow along its yaw, spawn_0 in red, the
// others in blue. `longer_side_px` sizes the picture.
// @throws std::runtime_error when the world does not compile or the PNG cannot be written.
void WriteWorldPreview(const std::filesystem::path& world_mjcf, double robot_reach_m,
                       const std::filesystem::path& png, int longer_side_px = 600);

}  // namespace plywood::render
