#include "sim/config/yaml_tags.h"

#include <array>
#include <regex>
#include <string_view>

#include "sim/config/config_error.h"

namespace plywood::sim {
namespace {

// "?" is an untagged plain node, "!" a quoted scalar (both "non-specific" in YAML's terms).
bool IsStandardTag(const std::string& tag) {
  static constexpr std::array<std::string_view, 9> kStandard = {"?",
                                                                "!",
                                                                "tag:yaml.org,2002:str",
                                                                "tag:yaml.org,2002:int",
                                                                "tag:yaml.org,2002:float",
                                                                "tag:yaml.org,2002:bool",
                                                                "tag:yaml.org,2002:null",
                                                                "tag:yaml.org,2002:map",
                                                                "tag:yaml.org,2002:seq"};
  for (std::string_view standard : kStandard) {
    if (tag == standard) return true;
  }
  return tag.empty();  // a node yaml-cpp made itself (an empty document)
}

// What a core-schema tag says the node is, when the node is not that (YAML 1.2's core schema):
// `duration_s: !!bool 0.2` was read as 0.2, the tag that said it could not be a number ignored.
// An !!int scalar is also a valid !!float (7 reads as 7.0); !!str takes any scalar.
std::string WhatTheTagAsks(const YAML::Node& node) {
  const std::string& tag = node.Tag();
  if (tag == "tag:yaml.org,2002:map") return node.IsMap() ? "" : "a map";
  if (tag == "tag:yaml.org,2002:seq") return node.IsSequence() ? "" : "a list";
  if (tag == "tag:yaml.org,2002:str") return node.IsMap() || node.IsSequence() ? "a string" : "";
  const auto scalar_matching = [&](const char* pattern, const char* what) -> std::string {
    if (node.IsScalar() && std::regex_match(node.Scalar(), std::regex(pattern))) return "";
    return what;
  };
  if (tag == "tag:yaml.org,2002:null") {
    if (node.IsNull()) return "";
    return scalar_matching("null|Null|NULL|~|", "null (null, ~ or nothing)");
  }
  if (tag == "tag:yaml.org,2002:bool") {
    return scalar_matching("true|True|TRUE|false|False|FALSE", "a boolean (true or false)");
  }
  if (tag == "tag:yaml.org,2002:int") {
    return scalar_matching("[-+]?[0-9]+|0o[0-7]+|0x[0-9a-fA-F]+", "a whole number");
  }
  if (tag == "tag:yaml.org,2002:float") {
    return scalar_matching(
        "[-+]?(\\.[0-9]+|[0-9]+(\\.[0-9]*)?)([eE][-+]?[0-9]+)?|[-+]?\\.(inf|Inf|INF)|\\.(nan|NaN|"
        "NAN)",
        "a number");
  }
  return "";
}

}  // namespace

void RejectNonStandardTags(const YAML::Node& node, const std::string& file,
                           const std::string& path) {
  if (!node.IsDefined()) return;
  if (!IsStandardTag(node.Tag())) {
    throw ConfigError(file, path.empty() ? "(top level)" : path,
                      "the YAML tag '" + node.Tag() +
                          "' means nothing here (only YAML's own !!str, !!int, !!float, !!bool, "
                          "!!null, !!map and !!seq do): write the value without it");
  }
  if (const std::string asked = WhatTheTagAsks(node); !asked.empty()) {
    const std::string shown = node.IsScalar()     ? "'" + node.Scalar() + "'"
                              : node.IsMap()      ? "a map"
                              : node.IsSequence() ? "a list"
                                                  : "nothing";
    const std::string core = "tag:yaml.org,2002:";
    const std::string written = "!!" + node.Tag().substr(core.size());  // as the file spells it
    throw ConfigError(file, path.empty() ? "(top level)" : path,
                      "the YAML tag '" + written + "' says " + asked + ", but the value is " +
                          shown + ": drop the tag or write the value it names");
  }
  const auto child_path = [&](const std::string& key) {
    return path.empty() ? key : path + "." + key;
  };
  if (node.IsMap()) {
    for (const auto& entry : node) {
      const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "?";
      RejectNonStandardTags(entry.first, file, child_path(key));
      RejectNonStandardTags(entry.second, file, child_path(key));
    }
  } else if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      RejectNonStandardTags(node[i], file, path + "[" + std::to_string(i) + "]");
    }
  }
}

}  // namespace plywood::sim
