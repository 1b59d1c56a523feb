#pragma once

#include "eval/protocol.h"

namespace plywood::eval {

// `protocol: seed000_rooms` (Souza, Becker, Rodrigues; seed 000): two back-to-back LMS 200 at the
// origin of each room (eval/lines/seed000_rooms.h), every extractor of the `lines:` section (all
// five by default). Prints lines found vs walls visible within the range cut, the data reduction
// and recall / precision per extractor and room; writes metrics.json (seed000.<room>.* and
// lines.<extractor>.* over all rooms), rooms.csv, timing.json, config.yaml and <room>.png.
int Seed000Protocol(const ProtocolContext& context);
// Reads the `seed000_rooms:` section and picks the rooms as the protocol does.
// @throws sim::ConfigError.
void CheckSeed000Options(const sim::ExperimentConfig& config);
// The rooms' world files the protocol runs besides config.world_path: the later rooms when the
// experiment's world is the first room's, else none. @throws sim::ConfigError.
std::vector<std::filesystem::path> Seed000OtherWorlds(const sim::ExperimentConfig& config);

}  // namespace plywood::eval
