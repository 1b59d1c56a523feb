#pragma once

#include <string>
#include <vector>

namespace plywood::apps {

// plywood worlds generate FAMILY --count N --seed S --out DIR [--pictures] [--quiet]
// plywood worlds list
// Writes N seeded worlds of a generator family (sim/world/generator/world_generator.h) with their
// sidecars and index.csv; --pictures adds a top-down PNG per world. Returns the exit code.
int WorldsCommand(const std::vector<std::string>& args);

}  // namespace plywood::apps
