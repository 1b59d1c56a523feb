#pragma once

#include <filesystem>

#include "viewer/frame_content.h"

namespace plywood::viewer {

// The maps a finished run wrote, for its replay: seed 001's cognitive_map.json (partitions and the
// graph's arcs through their doors) and seed 003's geometric_map.json (real and pseudo segments,
// clusters; unconfirmed segments are left out, as geometric_map.png leaves them out). The files
// hold the final maps only.
// @throws sim::ConfigError naming the file and field when a file is not what the run writes.
MapView ReadCognitiveMapFile(const std::filesystem::path& path);
GeometricMapView ReadGeometricMapFile(const std::filesystem::path& path);

}  // namespace plywood::viewer
