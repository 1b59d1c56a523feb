#include "sim/config/yaml_text_value.h"

#include <yaml-cpp/yaml.h>

namespace plywood::sim {

std::string YamlTextValue(const std::string& text) {
  try {
    const YAML::Node read = YAML::Load(text);
    if (read.IsScalar() && read.Scalar() == text) return text;
  } catch (const YAML::Exception&) {
    // Not YAML on its own ("a: b: c"): quoted below.
  }
  YAML::Emitter out;
  out << YAML::DoubleQuoted << text;
  return out.c_str();
}

}  // namespace plywood::sim
