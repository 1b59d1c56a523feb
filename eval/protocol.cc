#include "eval/protocol.h"

#include <cstdio>

#include "eval/lines/seed000_protocol.h"
#include "eval/lines/seed004_ransac_protocol.h"
#include "eval/odometry/umbmark_protocol.h"
#include "eval/odometry/weighted_gain_protocol.h"
#include "eval/single_run_protocol.h"
#include "sim/config/config_error.h"
#include "sim/runner/run_directory.h"

namespace plywood::eval {

const std::vector<Protocol>& Protocols() {
  static const std::vector<Protocol> protocols{
      {"single", "one run: sensors, estimators, controller and every post-run scorer",
       SingleRunProtocol, nullptr, nullptr},
      {"seed000_rooms", "seed 000: two back-to-back LMS 200 in each room, every line extractor",
       Seed000Protocol, CheckSeed000Options, Seed000OtherWorlds},
      {"seed004_ransac", "seed 004: RANSAC lines on the point cloud of a whole run",
       Seed004RansacProtocol, CheckSeed004RansacOptions, nullptr},
      {"umbmark", "Borenstein & Feng's UMBmark: 5 + 5 squares, calibration, 5 + 5 again",
       UmbmarkProtocol, CheckUmbmarkOptions, nullptr},
      {"weighted_gain_search", "seed 004: grid search of the weighted fusion's gains",
       WeightedGainProtocol, CheckWeightedGainOptions, nullptr},
  };
  return protocols;
}

const Protocol& FindProtocol(const sim::ExperimentConfig& config) {
  std::string known;
  for (const Protocol& protocol : Protocols()) {
    if (protocol.name == config.protocol) return protocol;
    known += (known.empty() ? "" : ", ") + protocol.name;
  }
  throw sim::ConfigError(config.source_file, "protocol",
                         "unknown protocol '" + config.protocol + "' (known: " + known + ")");
}

void CheckProtocolOptions(const sim::ExperimentConfig& config) {
  const Protocol& protocol = FindProtocol(config);
  if (protocol.check_options) protocol.check_options(config);
}

std::vector<std::filesystem::path> ProtocolOtherWorlds(const sim::ExperimentConfig& config) {
  const Protocol& protocol = FindProtocol(config);
  return protocol.other_worlds ? protocol.other_worlds(config)
                               : std::vector<std::filesystem::path>{};
}

void RequireObservableProtocol(const sim::ExperimentConfig& config, const std::string& what) {
  if (FindProtocol(config).name != "single") {
    throw sim::ConfigError(config.source_file, "protocol",
                           what + " shows single runs only, not protocol '" + config.protocol +
                               "' (its runs are separate experiments)");
  }
}

int RunProtocol(const ProtocolContext& context) {
  if (context.observer) RequireObservableProtocol(context.config, "an observer");
  const Protocol& protocol = FindProtocol(context.config);
  sim::StagedRunDirectory staged(context.out_dir, context.force);
  ProtocolContext inside = context;
  inside.out_dir = staged.staging();
  const int code = protocol.run(inside);
  if (code != 0) return code;
  staged.Commit();
  if (!context.quiet) std::printf("%-34s %s\n", "results", context.out_dir.c_str());
  return 0;
}

}  // namespace plywood::eval
