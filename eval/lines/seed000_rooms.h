#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "eval/lines/back_to_back_scans.h"
#include "eval/lines/line_scan_scorer.h"
#include "sim/config/experiment_config.h"

namespace plywood::eval {

// One room of seed 000's protocol: the world, the paper's range cut for it and the number of
// lines the paper reports there (0: not from the paper).
struct Seed000Room {
  std::string world;
  std::filesystem::path world_path;  // resolved
  double range_cut_m = 4.0;
  int paper_lines = 0;
  // Where the rig stands, facing +x rotated by rig_theta_deg (the paper: each room's origin).
  Eigen::Vector2d rig_W = Eigen::Vector2d::Zero();
  double rig_theta_deg = 0.0;
  // True when rig_W is the experiment's robot.spawn (rig_at: spawn), false at the origin.
  bool rig_at_spawn = false;
};

// The `seed000_rooms:` section of `protocol: seed000_rooms`:
//   seed000_rooms:
//     scans: 10                 # back-to-back scan pairs per room (independent noise)
//     range_cut_m: 4            # for a world given with --set world=PATH
//     rooms: [{world: worlds/seed000_room_1.xml, range_cut_m: 4, paper_lines: 7}, ...]
// The rooms run when the experiment's `world` is the first room's (the file's default); a later
// room's world runs that room alone, as its entry says; any other world (--set world=PATH) runs
// alone with range_cut_m, sensors at its origin (or at robot.spawn, rig_at: spawn).
struct Seed000RoomsOptions {
  int scans = 10;
  double range_cut_m = 4.0;
  // For a world given with --set world=PATH: "origin" (the paper's placement) or "spawn" (the
  // experiment's robot.spawn, which a sweep over generated worlds sets to a free spot).
  std::string rig_at = "origin";
  // OPTION, off by default (not part of seed 000's per-scan protocol): every scan of the rig
  // replaced by the per-beam median of its `scans` scans from the one pose (a beam with a return
  // in fewer than half of them gives none), so each extractor sees the same lower-noise scan
  // `scans` times. Set the extractors' noise (breakpoints.sigma_m) to match (docs/lines.md).
  bool median_of_scans = false;
  // The spot's scans as evidence for round objects: every scan keeps its own lines, scored on
  // its own, but split_and_merge also runs once on the per-beam median of the `scans` scans (its
  // noise sigma scaled to the median's, 1.25 / sqrt(scans)), and every extractor's line that is a
  // chord of a round object found there is dropped from each scan
  // (perception/lines/round_objects_of_quiet_scan.h; docs/lines.md, stops 63 and 65).
  // `round_objects_from_scans` reads true, false or auto: true refuses a setup that gives it
  // nothing to go on (one scan, median_of_scans, no noise, split_and_merge's round-object stage
  // off); auto (the shipped experiment's) uses the spot wherever it has that evidence and stays
  // off elsewhere; false (the default of a file that does not name it) never does.
  enum class SpotRoundObjects { kOff, kOn, kAuto };
  SpotRoundObjects round_objects_mode = SpotRoundObjects::kOff;
  // What the run does: the mode resolved against scans, median_of_scans and the extractors' noise.
  bool round_objects_from_scans = false;
  std::vector<Seed000Room> rooms;
};

// @throws sim::ConfigError naming the field.
Seed000RoomsOptions ReadSeed000RoomsOptions(const sim::ExperimentConfig& config);

// The rooms the protocol runs for `config` (see Seed000RoomsOptions).
std::vector<Seed000Room> RoomsToRun(const sim::ExperimentConfig& config,
                                    const Seed000RoomsOptions& options);

// What one room gave: the scan pairs, and each extractor's score over them.
struct Seed000RoomResult {
  Seed000Room room;
  BackToBackScans rig;
  std::vector<TruthScan> scans;
  std::vector<ExtractorScore> scores;  // in config.lines.extractors order (all five by default)
  // The round objects found in the median of the spot's scans, in the rig's frame (empty unless
  // round_objects_from_scans is in use); every extractor's chords of them were dropped.
  std::vector<perception::CircleFeature> spot_round_objects;
  double WallsVisible() const;   // observable ground-truth faces per scan
  double PointsPerScan() const;  // all beams of the pair (722 at 0.5 deg)
};

// Two back-to-back lasers at the room's origin facing +x and -x, `scans` pairs, every extractor.
Seed000RoomResult RunSeed000Room(const sim::ExperimentConfig& config, const Seed000Room& room,
                                 int scans, bool median_of_scans = false,
                                 bool round_objects_from_scans = false);

}  // namespace plywood::eval
