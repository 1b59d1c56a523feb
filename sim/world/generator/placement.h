#pragma once

#include <vector>

#include "sim/world/generator/footprint_2d.h"
#include "sim/world/generator/generated_world.h"

namespace plywood::sim::worldgen {

// Smallest distance from `candidate` to the world's geoms (0 when touching or overlapping),
// skipping the geoms whose indices are in `skip`.
double DistanceToGeoms(const GeneratedWorld& world, const Footprint& candidate,
                       const std::vector<int>& skip = {});

// True when the footprint lies inside one of the world's interior outlines (every corner; for a
// disc, its centre and four extreme points).
bool FootprintInsideInteriors(const GeneratedWorld& world, const Footprint& candidate);

// True when `candidate` lies inside the interiors and keeps at least `gap_m` from every geom.
bool Fits(const GeneratedWorld& world, const Footprint& candidate, double gap_m);

// Like Fits, but the candidate may also stand against a wall (touching, not overlapping it): to
// each wall it keeps either 0 or at least `gap_m`, so no slit narrower than `gap_m` opens
// anywhere; to everything else at least `gap_m`.
bool FitsAgainstWalls(const GeneratedWorld& world, const Footprint& candidate, double gap_m);

// Shuffles `items` with the world's draws (Fisher-Yates).
template <class T, class Rng>
void Shuffle(std::vector<T>& items, Rng& rng) {
  for (int i = static_cast<int>(items.size()) - 1; i > 0; --i) {
    std::swap(items[i], items[rng.Int(0, i)]);
  }
}

}  // namespace plywood::sim::worldgen
