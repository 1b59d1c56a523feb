#pragma once

#include <mujoco/mujoco.h>

#include <array>
#include <optional>

namespace plywood::sim {

// A world's free spots, <custom><numeric name="spawn_K" data="x_m y_m yaw_deg"/>
// (worlds/README.md): spawn K's three numbers as the model holds them (not checked for finiteness:
// each reader decides what a bad one means), or nullopt when the model has no such three-number
// entry.
std::optional<std::array<double, 3>> WorldSpawn(const mjModel* m, int k);

// How many numbers spawn K holds (3 when well formed), or -1 when the model has no spawn K: a
// reader tells a malformed entry (data="-2") from a missing one.
int WorldSpawnValueCount(const mjModel* m, int k);

}  // namespace plywood::sim
