#pragma once

#include <mujoco/mujoco.h>

#include <optional>
#include <string>

namespace plywood::sim {

// The first body or geom whose pos, quat or size is not a finite number, as "geom 'NAME': pos is
// not a finite number (nan 0 0.5)"; nullopt when all are finite. MuJoCo compiles pos="nan 0 0"
// without a word: such a geom is nowhere, every figure would silently ignore it, and the planar
// drive's obstacle grid cannot place it.
std::optional<std::string> NonFiniteGeometry(const mjModel* m);

}  // namespace plywood::sim
