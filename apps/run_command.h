#pragma once

#include <string>
#include <vector>

namespace plywood::apps {

// plywood run EXPERIMENT.yaml [--out DIR] [--seed N] [--set key.path=value]... [--quiet]
// Returns the process exit code; bad input throws (see plywood_main.cc).
int RunCommand(const std::vector<std::string>& args);

}  // namespace plywood::apps
