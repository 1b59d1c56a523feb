#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "perception/sonar_map/cognitive_map.h"

namespace plywood::eval {

// Seed 001's cognitive map as a JSON document, for a person or a script to read after a run: the
// room, the obstacles, the corners, every partition with its label, D as pairs of partition
// indices (lower first) and the topological graph (nodes, and arcs with the two ends of their
// shared stretch). Members in that order.
nlohmann::ordered_json CognitiveMapJson(const perception::CognitiveMap& map);

// CognitiveMapJson as text: one item per line (sim::WriteJson), lengths in metres with 4 decimals
// (0.1 mm) so the same map gives the same bytes; a non-finite number is written as null.
std::string CognitiveMapToJson(const perception::CognitiveMap& map);

}  // namespace plywood::eval
