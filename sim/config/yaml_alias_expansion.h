#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace plywood::sim {

// Every reader of a YAML tree (the duplicate-key check, the config readers, YAML::Clone) walks an
// alias (`*name`) again at each use, so ten lines of nested aliases ("billion laughs") expand to
// 10^10 nodes and a run that never starts. No config comes near this many nodes (20,000 waypoints
// are 60,000).
inline constexpr long kMaxYamlNodes = 1000000;

// @throws ConfigError naming `file` and the path where the walk passed kMaxYamlNodes nodes,
// counting each alias at every use. Stops as soon as it passes the limit, so it is cheap.
void RejectAliasExpansion(const YAML::Node& node, const std::string& file);

}  // namespace plywood::sim
