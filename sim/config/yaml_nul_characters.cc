#include "sim/config/yaml_nul_characters.h"

#include "sim/config/config_error.h"

namespace plywood::sim {
namespace {

// The text before the NUL: the one part of the value that can be printed.
void RejectIfHoldsNul(const std::string& text, const std::string& file, const std::string& path) {
  const std::size_t nul = text.find('\0');
  if (nul == std::string::npos) return;
  throw ConfigError(file, path.empty() ? "(top level)" : path,
                    "holds a NUL character (YAML's \\0) after '" + text.substr(0, nul) +
                        "': no name, path or option can hold one; remove it");
}

}  // namespace

void RejectNulCharacters(const YAML::Node& node, const std::string& file, const std::string& path) {
  if (!node.IsDefined()) return;
  if (node.IsScalar()) RejectIfHoldsNul(node.Scalar(), file, path);
  const auto child_path = [&](const std::string& key) {
    return path.empty() ? key : path + "." + key;
  };
  if (node.IsMap()) {
    for (const auto& entry : node) {
      if (entry.first.IsScalar()) {
        const std::string& key = entry.first.Scalar();
        RejectIfHoldsNul(key, file, child_path(key.substr(0, key.find('\0'))));
      }
      const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "?";
      RejectNulCharacters(entry.second, file, child_path(key));
    }
  } else if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      RejectNulCharacters(node[i], file, path + "[" + std::to_string(i) + "]");
    }
  }
}

}  // namespace plywood::sim
