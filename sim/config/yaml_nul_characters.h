#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace plywood::sim {

// YAML's "\0" escape puts a NUL character in a string, which no file name, path or option can
// hold: the C calls under std::filesystem cut the text there, so `name: "a\0b"` ran into runs/a
// (exit 1 on "plywood: error: runs/a") and `world: "hall.xml\0x"` loaded hall.xml, its errors
// printed cut short at the NUL (s57).
//
// @throws ConfigError naming `file` and the dotted path of the first key or value holding one.
void RejectNulCharacters(const YAML::Node& node, const std::string& file,
                         const std::string& path = "");

}  // namespace plywood::sim
