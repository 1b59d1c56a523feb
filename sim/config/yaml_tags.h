#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace plywood::sim {

// A YAML tag (`duration_s: !custom 10`, `!<tag:x> 1`, `%TAG` shorthands) asks the reader to
// construct the value as some type; the config readers know no tags and read the scalar as written,
// so a tag meant to change the value silently did not. Only YAML's core-schema tags (`!!str`,
// `!!int`, `!!float`, `!!bool`, `!!null`, `!!map`, `!!seq`) pass, and only on a value of the kind
// they name (core schema): the readers' type checks ask what the key needs, not what the tag says,
// so `!!bool 0.2` was read as the number 0.2 (s56).
//
// @throws ConfigError naming `file` and the dotted path of the first node with another tag, or
// with a core tag its value does not fit.
void RejectNonStandardTags(const YAML::Node& node, const std::string& file,
                           const std::string& path = "");

}  // namespace plywood::sim
