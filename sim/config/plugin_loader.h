#pragma once

#include <filesystem>
#include <string>

#include "perception/plugins/plugin.h"

namespace plywood::sim {

// The algorithms this process can create by name beyond the built-in ones: what the plug-ins
// named under an experiment's `plugins:` registered, and what was compiled in and added with
// RegisterAlgorithms. The config readers, the runner and the scorers all look names up here
// (docs/plugins.md). Registration happens while experiments are read; register before running
// anything on several threads.
const perception::AlgorithmRegistry& RegisteredAlgorithms();

// Adds every entry of `additions` to RegisteredAlgorithms(), all or none.
// @throws std::invalid_argument (one line) when a name is a built-in one, a key of its YAML
// section (lines.scoring, odometry.calibration, ...) or already registered.
void RegisterAlgorithms(const perception::AlgorithmRegistry& additions);

// Who registered the algorithm `name` of `kind` ("line extractor", "odometry estimator",
// "controller"), for the errors its run-time misbehaviour ends a run with: "plug-in LIBRARY" for
// one a plug-in registered (LIBRARY as the experiment named it), "registered" for one added with
// RegisterAlgorithms.
std::string RegisteredBy(const std::string& kind, const std::string& name);

// Loads the plug-in `library` (dlopen, RTLD_NOW | RTLD_LOCAL; never unloaded, since the
// algorithms it made live in the host), checks that it was built like this host
// (PLYWOOD_PLUGIN_ABI), calls its entry point with an empty registry and registers what it added.
// Loading the same file again does nothing.
// @throws std::invalid_argument (one line naming `library`) when it cannot be loaded, has no entry
// point, was built differently, or registers a name that is taken.
void LoadPlugin(const std::filesystem::path& library);

}  // namespace plywood::sim
