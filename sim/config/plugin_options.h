#pragma once

#include <yaml-cpp/yaml.h>

#include <functional>
#include <set>
#include <string>

#include "robot/plugins/parameter_map.h"

namespace plywood::sim {

class YamlFields;

// A registered algorithm's options as YAML: a flat mapping of scalars, kept as written
// (`my_filter: {gain: 0.5}`), except the keys in `skip` (read by the caller).
// @throws ConfigError naming the key for a value that is a list or a mapping.
robot::ParameterMap ReadPluginOptions(YamlFields& fields, const std::set<std::string>& skip = {});

// The same options as written into config.yaml (text as given, so a re-run reads the same).
void WritePluginOptions(const robot::ParameterMap& options, YAML::Node& node);

// Runs `build`, which makes a registered algorithm from its options, and reports what it throws
// as a ConfigError at `fields`' path: "lines.my_extractor.min_points: expected ...".
void CheckPluginBuild(const YamlFields& fields, const std::function<void()>& build);

}  // namespace plywood::sim
