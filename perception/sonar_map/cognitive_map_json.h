#pragma once

#include <string>

#include "perception/sonar_map/cognitive_map.h"

namespace plywood::perception {

// Seed 001's cognitive map as JSON, for a person or a script to read after a run: the room, the
// obstacles, the corners, every partition with its label, D as pairs of partition indices (lower
// first) and the topological graph (nodes, and arcs with the two ends of their shared stretch).
// Lengths in metres with 4 decimals (0.1 mm), so the same map gives the same bytes; a non-finite
// number is written as null.
std::string CognitiveMapToJson(const CognitiveMap& map);

}  // namespace plywood::perception
