#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace plywood::eval {

// Worlds drawn by the world generator (`plywood worlds generate FAMILY --count N --seed S`).
struct GeneratedWorlds {
  std::string family;
  int count = 0;
  std::uint64_t seed = 1;
};

// One `set:` axis: a key path of the base experiment (as for `plywood run --set`) and its values,
// each kept as the YAML text that --set would take.
struct SweepAxis {
  std::string key;
  std::vector<std::string> values;
};

// A sweep file (docs/sweeps.md):
//   experiment: experiments/default.yaml   # a single run or a protocol experiment (or a list)
//   seeds: [1, 2, 3]                       # or {from: 1, to: 20}
//   worlds: [worlds/hall.xml]              # files, globs, or {family: room, count: 50, seed: 1},
//                                          # or a list mixing them
//   profiles: [experiments/profiles/ideal.set]  # files of --set lines, one axis value each
//   set: {duration_s: [20, 30], sensors.laser.range_noise_sigma_m: [0.005, 0.01]}
//   zip: [duration_s, sensors.laser.range_noise_sigma_m]   # these axes advance together
//   metrics: [odometry.encoder.drift_percent]             # summarised, printed and plotted
//   group_by: [family]        # summary groups besides experiment, profile and the set axes
// Every axis is crossed with every other, except the `zip` axes, which advance together.
struct SweepSpec {
  std::string source_file;                         // for error messages
  std::vector<std::filesystem::path> experiments;  // resolved; usually one
  std::string name;                  // the sweep file's stem unless `name:` says otherwise
  std::vector<std::uint64_t> seeds;  // empty: the experiment's own seed
  std::vector<std::filesystem::path> world_files;  // files and globs, resolved and sorted
  std::vector<GeneratedWorlds> generated;
  std::vector<std::filesystem::path> profiles;  // .set files: one --set line each
  std::vector<SweepAxis> axes;
  std::vector<std::string> zip;  // keys of `axes` that advance together
  std::vector<std::string> metrics;
  std::vector<std::string> group_by;  // "world" and/or "family"
  std::string text;                   // the file's bytes, to tell whether a sweep changed
};

// Reads and checks a sweep file. Paths resolve against the sweep file's folder, then the data root.
// @throws sim::ConfigError naming the file and the field (unknown key, empty list, bad range,
// unknown family, negative count, a glob that matches nothing, zip axes of unequal length, more
// than 100000 cells).
SweepSpec LoadSweepSpec(const std::filesystem::path& path);

}  // namespace plywood::eval
