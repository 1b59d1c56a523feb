#include "sim/config/yaml_tags.h"

#include <array>
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
