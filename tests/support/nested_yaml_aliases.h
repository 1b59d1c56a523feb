#pragma once

#include <string>

namespace plywood::testing {

// Ten top-level keys KEY0..KEY9, each a list of ten uses of the one before ("billion laughs"):
// ten short lines that expand to 10^10 nodes for every reader that walks the YAML tree.
inline std::string NestedYamlAliases(const std::string& key) {
  std::string yaml = key + "0: &" + key + "0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i < 10; ++i) {
    const std::string use = "*" + key + std::to_string(i - 1);
    yaml += key + std::to_string(i) + ": &" + key + std::to_string(i) + " [" + use;
    for (int j = 1; j < 10; ++j) yaml += ", " + use;
    yaml += "]\n";
  }
  return yaml;
}

}  // namespace plywood::testing
