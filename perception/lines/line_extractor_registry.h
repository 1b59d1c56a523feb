#pragma once

#include <functional>
#include <memory>
#include <string>

#include "perception/lines/line_extractor.h"
#include "robot/plugins/parameter_map.h"
#include "robot/plugins/registry.h"

namespace plywood::perception {

// A line extractor user code adds by name (docs/plugins.md). The factory gets the extractor's
// options and throws std::invalid_argument "<key>: <what is wrong>" for a bad one. The extractor
// must keep LineExtractor's contract: immutable, deterministic, safe from several threads.
struct RegisteredLineExtractor {
  std::string name;
  std::function<std::unique_ptr<LineExtractor>(const robot::ParameterMap& options)> make;
};

using LineExtractorRegistry = robot::Registry<RegisteredLineExtractor>;

}  // namespace plywood::perception
