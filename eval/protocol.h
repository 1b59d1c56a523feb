#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "sim/config/experiment_config.h"
#include "sim/runner/run_observer.h"

namespace plywood::eval {

// What a protocol gets: the loaded experiment (its own options in config.protocol_options, read
// strictly with sim::YamlFields), where to write, and whether to print progress and pictures.
struct ProtocolContext {
  const sim::ExperimentConfig& config;
  std::filesystem::path out_dir;
  bool quiet = false;
  bool snapshots = true;
  bool force = false;  // replace an earlier run in out_dir (sim::StagedRunDirectory)
  // Watches the run step by step (viewer, video); only the single-run protocol takes one (see
  // RequireObservableProtocol). Not owned; null: none.
  sim::RunObserver* observer = nullptr;
};

// One way of running and scoring an experiment: the plain run ("single") or a paper's multi-run
// protocol (UMBmark's 10 squares, seed 000's four rooms, ...). `plywood run`, sweeps and the tests
// all go through RunProtocol, so they run the same code. `run` returns the exit code; bad options
// throw sim::ConfigError naming the field.
struct Protocol {
  std::string name;
  std::string summary;  // one line for --help
  std::function<int(const ProtocolContext&)> run;
  // Reads the protocol's own section (config.protocol_options) as `run` does, running nothing, so
  // a sweep refuses a bad option when it loads rather than in every cell. Null: no options.
  // @throws sim::ConfigError naming the field.
  std::function<void(const sim::ExperimentConfig&)> check_options;
  // The world files a run of `config` reads besides config.world_path (seed 000's other rooms),
  // so a sweep hashes them into its cells' ids. Null: none.
  // @throws sim::ConfigError naming the field, as check_options.
  std::function<std::vector<std::filesystem::path>(const sim::ExperimentConfig&)> other_worlds;
};

// Every protocol, "single" first. Each lives in its own eval/<capability>/<name>_protocol.cc.
const std::vector<Protocol>& Protocols();

// The protocol named by config.protocol. @throws sim::ConfigError naming `protocol` when unknown.
const Protocol& FindProtocol(const sim::ExperimentConfig& config);

// Reads config.protocol's options (Protocol::check_options) without running anything.
// @throws sim::ConfigError naming `protocol` when unknown, or the bad option.
void CheckProtocolOptions(const sim::ExperimentConfig& config);

// The world files config.protocol reads besides config.world_path (Protocol::other_worlds).
// @throws sim::ConfigError naming `protocol` when unknown, or a bad option.
std::vector<std::filesystem::path> ProtocolOtherWorlds(const sim::ExperimentConfig& config);

// @throws sim::ConfigError naming `protocol` when config.protocol cannot show its run to an
// observer (`what`, e.g. "the viewer", names who asked).
void RequireObservableProtocol(const sim::ExperimentConfig& config, const std::string& what);

// Runs config.protocol with `context`: out_dir is checked first (sim::StagedRunDirectory, before
// anything is simulated), the protocol writes into a staging folder beside it, and the folder is
// renamed to out_dir with its completion marker only when the protocol returns 0. Prints the
// results line unless quiet.
int RunProtocol(const ProtocolContext& context);

}  // namespace plywood::eval
