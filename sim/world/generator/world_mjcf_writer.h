#pragma once

#include <string>

#include "sim/world/generator/generated_world.h"

namespace plywood::sim::worldgen {

// The world as a standalone MJCF following worlds/README.md: the shipped worlds' materials and
// default classes, spawn poses as <numeric name="spawn_K" data="x_m y_m yaw_deg"/>, a floor plane
// under the geometry and every geom static in <worldbody>. Numbers carry at most 6 decimals.
std::string WorldMjcf(const GeneratedWorld& world);

// The sidecar: family, seed, index, the drawn parameters, spawn poses and a few figures for
// tables, as one JSON object.
std::string WorldSidecarJson(const GeneratedWorld& world);

}  // namespace plywood::sim::worldgen
