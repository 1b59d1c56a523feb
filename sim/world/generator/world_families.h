#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sim/world/generator/generated_world.h"
#include "sim/world/generator/world_rng.h"

namespace plywood::sim::worldgen {

// Draws one layout of a family in its local frame: geoms, interiors, parameters, summary and
// `closed`. Returns the rotation (deg) that turns the local frame into the world's, or nothing
// when the drawn layout does not fit (the generator then draws again from the same stream).
// Parameter ranges: docs/worlds.md.
using FamilyDraw = std::optional<double> (*)(WorldRng& rng, GeneratedWorld& world);

struct WorldFamily {
  std::string name;
  std::string description;  // one line
  int spawns = 3;           // spawn poses per world
  FamilyDraw draw = nullptr;
};

// room, doorways, columns, clutter, stubs, corridor, seed001, office (in that order).
const std::vector<WorldFamily>& WorldFamilies();

// @throws std::invalid_argument "family: unknown world family 'x' (known: room, ...)".
const WorldFamily& FindWorldFamily(const std::string& name);

std::optional<double> DrawRoomWorld(WorldRng& rng, GeneratedWorld& world);
std::optional<double> DrawDoorwaysWorld(WorldRng& rng, GeneratedWorld& world);
std::optional<double> DrawColumnsWorld(WorldRng& rng, GeneratedWorld& world);
std::optional<double> DrawClutterWorld(WorldRng& rng, GeneratedWorld& world);
std::optional<double> DrawStubsWorld(WorldRng& rng, GeneratedWorld& world);
std::optional<double> DrawCorridorWorld(WorldRng& rng, GeneratedWorld& world);
std::optional<double> DrawSeed001World(WorldRng& rng, GeneratedWorld& world);
std::optional<double> DrawOfficeWorld(WorldRng& rng, GeneratedWorld& world);

}  // namespace plywood::sim::worldgen
