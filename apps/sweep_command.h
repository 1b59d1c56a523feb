#pragma once

#include <string>
#include <vector>

namespace plywood::apps {

// plywood sweep SWEEP.yaml [--jobs N] [--out DIR] [--shard I/N] [--slurm ...] | --collect DIR
int SweepCommand(const std::vector<std::string>& args);

}  // namespace plywood::apps
