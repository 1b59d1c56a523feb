#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace plywood::eval {

struct SweepMetaDamage {
  std::string field;  // "" for the whole file
  std::string what;
};

// What is wrong with a sweep folder's parsed sweep.json (nullopt when it is whole): it must be an
// object whose fields, where present, have the types the sweep writes. A file cut, edited or
// written by something else is then reported (--collect) or the sweep started again (resume)
// instead of failing deep inside on a JSON type error.
std::optional<SweepMetaDamage> FindSweepMetaDamage(const nlohmann::json& meta);

}  // namespace plywood::eval
