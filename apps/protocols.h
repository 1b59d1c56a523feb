#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include "sim/experiment_config.h"

namespace plywood::apps {

// What a protocol gets: the loaded experiment (its own options in config.protocol_options, read
// strictly with sim::YamlFields), where to write, and whether to print progress.
struct ProtocolContext {
  const sim::ExperimentConfig& config;
  std::filesystem::path out_dir;
  bool quiet = false;
  bool snapshots = true;
};

// A multi-run experiment (UMBmark's 10 squares, seed 000's four rooms, ...). Returns the exit code;
// bad options throw sim::ConfigError.
using Protocol = std::function<int(const ProtocolContext&)>;

// name -> protocol; "single" is the plain run of plywood run.
const std::map<std::string, Protocol>& Protocols();

}  // namespace plywood::apps
