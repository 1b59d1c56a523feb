#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace plywood::sim {

// A YAML tag (`duration_s: !custom 10`, `!<tag:x> 1`, `%TAG` shorthands) asks the reader to
// construct the value as some type; the config readers know no tags and read the scalar as written,
// so a tag meant to change the value silently did not. Only YAML's core-schema tags (`!!str`,
// `!!int`, `!!float`, `!!bool`, `!!null`, `!!map`, `!!seq`), whose meaning the readers' own type
// checks already enforce, pass.
//
// @throws ConfigError naming `file` and the dotted path of the first node with another tag.
void RejectNonStandardTags(const YAML::Node& node, const std::string& file,
                           const std::string& path = "");

}  // namespace plywood::sim
