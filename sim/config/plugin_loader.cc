#include "sim/config/plugin_loader.h"

#include <dlfcn.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sim/config/controller_config.h"
#include "sim/config/lines_config.h"
#include "sim/config/odometry_config.h"

namespace plywood::sim {
namespace {

perception::AlgorithmRegistry& MutableRegistry() {
  static perception::AlgorithmRegistry registry;
  return registry;
}

// The library each registered (kind, name) came from; absent: compiled in.
std::map<std::pair<std::string, std::string>, std::string>& Libraries() {
  static std::map<std::pair<std::string, std::string>, std::string> libraries;
  return libraries;
}

// RegisterAlgorithms, remembering `library` ("" when compiled in) as each name's origin.
void RegisterAlgorithmsFrom(const perception::AlgorithmRegistry& additions,
                            const std::string& library) {
  RegisterAlgorithms(additions);
  if (library.empty()) return;
  const auto remember = [&](const auto& registry, const char* kind) {
    for (const auto& entry : registry.entries()) Libraries()[{kind, entry.name}] = library;
  };
  remember(additions.line_extractors, "line extractor");
  remember(additions.odometry_estimators, "odometry estimator");
  remember(additions.controllers, "controller");
}

// Throws when `name` is taken by a built-in algorithm, a section key or an earlier registration.
template <typename Registry>
void CheckName(const std::string& name, const std::vector<std::string>& taken,
               const Registry& registered, const char* kind) {
  if (std::find(taken.begin(), taken.end(), name) != taken.end()) {
    throw std::invalid_argument("registers " + std::string(kind) + " '" + name +
                                "', a name Plywood already uses");
  }
  if (registered.Find(name)) {
    throw std::invalid_argument("registers " + std::string(kind) + " '" + name +
                                "', which is already registered");
  }
}

// dlerror() repeats the file name first; drop it since the message names the file already.
std::string LoaderError(const std::filesystem::path& library) {
  const char* error = dlerror();
  std::string text = error ? error : "unknown error";
  const std::string prefix = library.string() + ": ";
  if (text.rfind(prefix, 0) == 0) text.erase(0, prefix.size());
  return text;
}

}  // namespace

const perception::AlgorithmRegistry& RegisteredAlgorithms() { return MutableRegistry(); }

void RegisterAlgorithms(const perception::AlgorithmRegistry& additions) {
  perception::AlgorithmRegistry& registry = MutableRegistry();
  // Check everything first (also names repeated inside `additions`), then add: all or none.
  perception::AlgorithmRegistry checked = registry;
  for (const auto& entry : additions.line_extractors.entries()) {
    CheckName(entry.name, TakenLinesKeys(), checked.line_extractors, "line extractor");
    checked.line_extractors.Add(entry);
  }
  for (const auto& entry : additions.odometry_estimators.entries()) {
    CheckName(entry.name, TakenOdometryKeys(), checked.odometry_estimators, "odometry estimator");
    checked.odometry_estimators.Add(entry);
  }
  for (const auto& entry : additions.controllers.entries()) {
    CheckName(entry.name, BuiltInControllerTypes(), checked.controllers, "controller");
    checked.controllers.Add(entry);
  }
  registry = std::move(checked);
}

std::string RegisteredBy(const std::string& kind, const std::string& name) {
  const auto it = Libraries().find({kind, name});
  return it == Libraries().end() ? "registered" : "plug-in " + it->second;
}

void LoadPlugin(const std::filesystem::path& library) {
  static std::mutex mutex;
  // Every library loaded so far, with why its registration failed ("" when it did not).
  static std::map<std::filesystem::path, std::string> loaded;
  const std::lock_guard<std::mutex> lock(mutex);
  std::error_code error;
  const std::filesystem::path key = std::filesystem::canonical(library, error);
  if (error) throw std::invalid_argument(library.string() + ": no such file");
  if (const auto it = loaded.find(key); it != loaded.end()) {
    if (!it->second.empty()) throw std::invalid_argument(it->second);
    return;
  }

  const std::string name = library.string();
  void* handle = dlopen(key.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    throw std::invalid_argument(name + ": cannot load it as a shared library: " + LoaderError(key));
  }
  using AbiFunction = const char* (*)();
  using EntryFunction = void (*)(perception::AlgorithmRegistry*);
  const auto entry = reinterpret_cast<EntryFunction>(dlsym(handle, perception::kPluginEntryPoint));
  const auto abi = reinterpret_cast<AbiFunction>(dlsym(handle, perception::kPluginAbiSymbol));
  if (!entry || !abi) {
    dlclose(handle);
    throw std::invalid_argument(name + ": no " + perception::kPluginEntryPoint +
                                " entry point; define it with PLYWOOD_PLUGIN from "
                                "perception/plugins/plugin.h (docs/plugins.md)");
  }
  // A null pointer made std::string throw std::logic_error: exit 1 with libstdc++'s words.
  const char* claimed_abi = abi();
  if (claimed_abi == nullptr) {
    dlclose(handle);
    throw std::invalid_argument(name + ": its " + perception::kPluginAbiSymbol +
                                "() returns a null pointer, not the build it was made for; define "
                                "it with PLYWOOD_PLUGIN from perception/plugins/plugin.h "
                                "(docs/plugins.md)");
  }
  const std::string plugin_abi = claimed_abi;
  if (plugin_abi != PLYWOOD_PLUGIN_ABI) {
    dlclose(handle);
    throw std::invalid_argument(
        name + ": built for " + plugin_abi + ", but this plywood is " + PLYWOOD_PLUGIN_ABI +
        "; rebuild the plug-in against this Plywood with the same compiler");
  }
  // The library stays loaded from here on, even when registering fails: its code may already
  // have run (static constructors, a partial registration).
  std::string& failure = loaded[key];
  perception::AlgorithmRegistry additions;
  try {
    entry(&additions);
    RegisterAlgorithmsFrom(additions, name);
  } catch (const std::exception& e) {
    failure = name + ": " + e.what();
  } catch (...) {
    failure = name + ": its entry point threw an exception";
  }
  if (!failure.empty()) throw std::invalid_argument(failure);
}

}  // namespace plywood::sim
