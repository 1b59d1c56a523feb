#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "eval/sweep/sweep_spec.h"

namespace plywood::eval {

// One run of a sweep: the base experiment with `overrides` (the --set list of `plywood run`).
struct SweepCell {
  int index = 0;           // position in the sweep's fixed order
  std::string id;          // 16 hex digits: a stable hash of the resolved config
  std::string experiment;  // the base experiment file
  std::string world;       // as given (or the generated file's path); empty: the base's
  std::string family;      // generator family, empty for hand-made worlds
  std::string profile;     // the profile file's stem, empty without profiles
  std::uint64_t seed = 0;
  std::vector<std::string> values;  // one per SweepSpec::axes
  std::vector<std::string> overrides;
  // Files the run reads besides its world (sonar-net weights, plug-ins) with their contents'
  // hashes, in the order the run reads them: part of `id` and of sweep.json's inputs; not kept
  // in cells.json.
  std::vector<std::pair<std::filesystem::path, std::string>> read_files;
  // The robot model it runs (robot.model): its MJCF is hashed into sweep.json's robot_models, so a
  // resume after models/ was edited starts again; not kept in cells.json.
  std::string robot;
  // The hand-made world file the run loads (the experiment's own `world:`, a profile's or an axis'
  // as well as the worlds: axis'): sweep.json's inputs hash it, so a resume after it was edited
  // expands the sweep again; not kept in cells.json. Empty for generated worlds (hashed apart).
  std::filesystem::path world_file;
};

// A world the sweep runs in, with the family it was drawn from (empty for files).
struct SweepWorld {
  std::filesystem::path path;  // absolute
  std::string family;
  // Generated worlds live in the sweep folder and are named relative to it ("worlds/room-seed1/
  // room_s1_00000.xml"), so ids, cells and results do not depend on where the folder is.
  std::string label;  // empty: the path itself
};

// A cell's world override for a world inside the sweep folder starts with this; the runner puts
// the folder's absolute path in its place.
inline constexpr const char* kSweepFolderPrefix = "@SWEEP/";

// Every cell, in a fixed order: experiments outermost, then worlds, profiles, the set axes
// (crossed; zipped axes advance together), and seeds innermost. A world axis places the robot at
// the world's spawn_0 unless the sweep itself sets robot.spawn. Each cell's config is loaded and
// checked here, before anything runs, so a key path the experiment does not have fails the whole
// sweep at once.
// @throws sim::ConfigError naming the sweep file and the field.
std::vector<SweepCell> ExpandCells(const SweepSpec& spec, const std::vector<SweepWorld>& worlds);

// Checks every combination of the set values the cells will run, on top of each profile's lines,
// against every base experiment, so a key path the experiment does not have, or values it refuses
// together, fail before any world is generated or any run starts.
// @throws sim::ConfigError naming the sweep file and the field.
void CheckSweepOverrides(const SweepSpec& spec);

// The --set lines of a profile file ('#' comments and blank lines skipped).
// @throws sim::ConfigError naming the file and line.
std::vector<std::string> ReadProfile(const std::filesystem::path& path);

// StableHash of a world file's text and of every file it names (sim::ReferencedFiles), by their
// names relative to its folder: what a cell's id and sweep.json's inputs take the world to be.
std::string WorldContentHash(const std::filesystem::path& world);

// The hash a sweep records for a file its cells read besides their world: WorldContentHash for an
// MJCF world (.xml: seed 000's other rooms), else StableHash of the file's bytes (sonar-net
// weights, plug-ins).
std::string ReadFileContentHash(const std::filesystem::path& file);

// FNV-1a, 64 bit, as 16 hex digits: stable across machines and compilers.
std::string StableHash(const std::string& text);

}  // namespace plywood::eval
