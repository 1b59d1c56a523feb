#include "eval/sweep/sweep_meta.h"

#include <algorithm>

namespace plywood::eval {
namespace {

bool IsStringList(const nlohmann::json& value) {
  return value.is_array() && std::all_of(value.begin(), value.end(),
                                         [](const nlohmann::json& v) { return v.is_string(); });
}

bool IsStringMap(const nlohmann::json& value) {
  return value.is_object() && std::all_of(value.begin(), value.end(),
                                          [](const nlohmann::json& v) { return v.is_string(); });
}

}  // namespace

std::optional<SweepMetaDamage> FindSweepMetaDamage(const nlohmann::json& meta) {
  if (!meta.is_object()) return SweepMetaDamage{"", "expected a JSON object"};
  for (const char* key : {"name", "sweep_file", "plywood_build_id", "cells_json_hash"}) {
    if (meta.contains(key) && !meta[key].is_string()) return SweepMetaDamage{key, "expected text"};
  }
  for (const char* key : {"experiments", "axes", "metrics", "group_by"}) {
    if (meta.contains(key) && !IsStringList(meta[key])) {
      return SweepMetaDamage{key, "expected a list of text"};
    }
  }
  if (meta.contains("profiles") && !meta["profiles"].is_boolean()) {
    return SweepMetaDamage{"profiles", "expected true or false"};
  }
  if (meta.contains("cells") && !meta["cells"].is_number_unsigned()) {
    return SweepMetaDamage{"cells", "expected a whole number >= 0"};
  }
  if (meta.contains("inputs") && !IsStringMap(meta["inputs"])) {
    return SweepMetaDamage{"inputs", "expected a mapping of file to hash"};
  }
  if (meta.contains("robot_models") && !IsStringMap(meta["robot_models"])) {
    return SweepMetaDamage{"robot_models", "expected a mapping of robot to hash"};
  }
  return std::nullopt;
}

}  // namespace plywood::eval
