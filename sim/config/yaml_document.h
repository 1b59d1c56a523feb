#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace plywood::sim {

// The one YAML document of a config file's `text` (an undefined node for an empty file). A second
// document (after a `---` line) was read by nobody: YAML::Load keeps the first and drops the rest
// without a word, so an experiment or sweep pasted together from two files ran with half its
// settings. Empty documents after the first (a trailing `---`) are harmless and allowed.
// @throws ConfigError "<source>: not valid YAML: ..." or "<source>: line N: a second YAML
// document ..." naming where it begins.
YAML::Node LoadOneYamlDocument(const std::string& text, const std::string& source);

// A copy of `node` in which every alias (`*name`) is a node of its own. yaml-cpp makes an alias
// the very node its anchor names, so `--set sensors.laser.rate_hz=5` on a file with `laser:
// {rate_hz: &r 10}` and `sonar: {rate_hz: *r}` set the sonar's rate too. Tags are kept.
YAML::Node CopyWithoutSharedNodes(const YAML::Node& node);

}  // namespace plywood::sim
