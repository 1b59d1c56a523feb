#include "sim/config/plugin_options.h"

#include <stdexcept>

#include "sim/config/yaml_fields.h"

namespace plywood::sim {

robot::ParameterMap ReadPluginOptions(YamlFields& fields, const std::set<std::string>& skip) {
  robot::ParameterMap options;
  for (const std::string& key : fields.Keys()) {
    if (skip.count(key)) continue;
    const YAML::Node value = fields.Raw(key);
    if (!value.IsScalar()) {
      fields.Fail(key,
                  "expected a number, true/false or text (a registered algorithm's options are "
                  "one flat mapping)");
    }
    options.Set(key, value.Scalar());
  }
  return options;
}

void WritePluginOptions(const robot::ParameterMap& options, YAML::Node& node) {
  for (const auto& [key, value] : options.values()) node[key] = value;
}

void CheckPluginBuild(const YamlFields& fields, const std::function<void()>& build) {
  try {
    build();
  } catch (const std::exception& e) {
    fields.FailValidation(e.what());
  } catch (...) {
    fields.FailValidation("the plug-in's factory threw an exception that is not std::exception");
  }
}

}  // namespace plywood::sim
