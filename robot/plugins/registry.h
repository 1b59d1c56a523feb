#pragma once

// Header-only on purpose: a plug-in adds to the host's registry with this code (docs/plugins.md).

#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "robot/plugins/parameter_map.h"

namespace plywood::robot {

// Algorithms of one kind that can be created by name, beyond the built-in ones: user code adds an
// Entry (a struct with `name` and a factory `make`), the host looks names up. Names become YAML
// keys, metric keys and CSV column prefixes, so they are lower-case identifiers ([a-z][a-z0-9_]*).
// Entries keep the order they were added in.
template <typename Entry>
class Registry {
 public:
  // @throws std::invalid_argument when the name is not an identifier, is taken, or has no factory.
  void Add(Entry entry) {
    if (!IsIdentifier(entry.name)) {
      throw std::invalid_argument("'" + entry.name +
                                  "' is not a valid algorithm name (lower-case letters, digits "
                                  "and '_', starting with a letter)");
    }
    if (Find(entry.name)) {
      throw std::invalid_argument("'" + entry.name + "' is registered twice");
    }
    if (!entry.make) throw std::invalid_argument("'" + entry.name + "' has no factory");
    entries_.push_back(std::move(entry));
  }

  // The entry named `name`, or null.
  const Entry* Find(std::string_view name) const {
    for (const Entry& entry : entries_) {
      if (entry.name == name) return &entry;
    }
    return nullptr;
  }

  std::vector<std::string> Names() const {
    std::vector<std::string> names;
    for (const Entry& entry : entries_) names.push_back(entry.name);
    return names;
  }

  const std::vector<Entry>& entries() const { return entries_; }
  bool empty() const { return entries_.empty(); }

  static bool IsIdentifier(std::string_view name) {
    if (name.empty() || name[0] < 'a' || name[0] > 'z') return false;
    for (char c : name) {
      if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
    }
    return true;
  }

 private:
  std::vector<Entry> entries_;
};

// Builds a registered algorithm: calls entry.make(args..., options) and then checks that the
// factory read every option (ParameterMap::CheckAllRead), so a misspelt option is an error.
// @throws std::invalid_argument "<key>: <what is wrong>" from the factory or the check, or when
// the factory returns nothing.
template <typename Entry, typename... Args>
auto MakeRegistered(const Entry& entry, const ParameterMap& options, const Args&... args) {
  const ParameterMap fresh(options.values());  // reads counted for this build only
  auto made = entry.make(args..., fresh);
  fresh.CheckAllRead();
  if (!made) throw std::invalid_argument("the factory of '" + entry.name + "' returned nothing");
  return made;
}

}  // namespace plywood::robot
