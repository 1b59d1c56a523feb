#pragma once

#include <mujoco/mujoco.h>

#include <array>
#include <optional>
#include <string>

namespace plywood::sim {

// A world's free spots, <custom><numeric name="spawn_K" data="x_m y_m yaw_deg"/>
// (worlds/README.md): spawn K's three numbers as the model holds them (not checked for finiteness:
// each reader decides what a bad one means), or nullopt when the model has no such three-number
// entry.
std::optional<std::array<double, 3>> WorldSpawn(const mjModel* m, int k);

// The most a spawn heading may turn either way: every heading can be written within one turn, and
// far beyond it the double loses the degree (1e300 deg: spacing 1e284 deg).
inline constexpr double kMaxSpawnTurnDeg = 360.0;

// What makes spawn K unusable as a pose (not three numbers, not finite, a heading beyond
// kMaxSpawnTurnDeg; no numeric but a site, body, geom, text or tuple of its name), as one line for
// a "FILE: spawn_K: ..." error; nullopt when it is well formed or the model has none. One rule for
// every reader that places a robot there.
std::optional<std::string> WorldSpawnProblem(const mjModel* m, int k);

}  // namespace plywood::sim
