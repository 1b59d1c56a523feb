#pragma once

#include <filesystem>
#include <string>

namespace plywood::eval {

// An MJCF of `tiles_x` x `tiles_y` copies of `world_xml`'s world (plywood bench's tiled office):
// every worldbody geom but the floor plane is repeated in the worldbody, shifted by the tile's
// offset (tiles `pitch_x_m` x `pitch_y_m` apart, the original at the centre tile so its spawn
// poses still hold), and the floor plane is scaled to cover them all; names get a "_tI_J" suffix
// so they stay unique. The world must keep each geom on one line with pos="x y z", as the shipped
// worlds do, and name its floor plane "floor".
// @throws std::runtime_error when the file cannot be read or does not follow that layout.
std::string TiledWorldMjcf(const std::filesystem::path& world_xml, int tiles_x, int tiles_y,
                           double pitch_x_m, double pitch_y_m);

}  // namespace plywood::eval
