#include "sim/config/yaml_alias_expansion.h"

#include <vector>

#include "sim/config/config_error.h"

namespace plywood::sim {
namespace {

// The first three steps of the path are enough to find the culprit in the file (a deep path of
// "[0]" steps would be a very long line).
std::string ShortPath(const std::vector<std::string>& steps) {
  std::string path;
  for (std::size_t i = 0; i < steps.size() && i < 3; ++i) {
    path += (i > 0 && steps[i].rfind("[", 0) != 0 ? "." : "") + steps[i];
  }
  return path.empty() ? "(top level)" : path;
}

void Count(const YAML::Node& node, const std::string& file, std::vector<std::string>& steps,
           long& nodes) {
  if (++nodes > kMaxYamlNodes) {
    throw ConfigError(file, ShortPath(steps),
                      "the document expands to more than " + std::to_string(kMaxYamlNodes) +
                          " YAML nodes (each alias *name counts at every use): too large for a "
                          "config; write the values out or use fewer nested aliases");
  }
  if (node.IsMap()) {
    for (const auto& entry : node) {
      steps.push_back(entry.first.IsScalar() ? entry.first.Scalar() : "?");
      Count(entry.second, file, steps, nodes);
      steps.pop_back();
    }
  } else if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      steps.push_back("[" + std::to_string(i) + "]");
      Count(node[i], file, steps, nodes);
      steps.pop_back();
    }
  }
}

}  // namespace

void RejectAliasExpansion(const YAML::Node& node, const std::string& file) {
  std::vector<std::string> steps;
  long nodes = 0;
  Count(node, file, steps, nodes);
}

}  // namespace plywood::sim
