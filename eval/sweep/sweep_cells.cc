#include "eval/sweep/sweep_cells.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <tuple>
#include <utility>

#include "eval/protocol.h"
#include "msgs/angle_units.h"
#include "msgs/stable_hash.h"
#include "perception/logs/byte_order_mark.h"
#include "perception/logs/regular_file.h"
#include "sim/config/config_error.h"
#include "sim/config/experiment_config.h"
#include "sim/config/robot_catalog.h"
#include "sim/config/utf8_text.h"
#include "sim/config/yaml_text_value.h"
#include "sim/runner/checked_scene.h"
#include "sim/runner/controller_targets.h"
#include "sim/runner/out_of_memory.h"
#include "sim/runner/sensors_the_config_needs.h"
#include "sim/runner/spawn_refused.h"
#include "sim/runner/text_file.h"
#include "sim/world/mujoco_handles.h"
#include "sim/world/referenced_files.h"
#include "sim/world/world_spawns.h"

namespace plywood::eval {
namespace {

// The combinations of the set axes, in order: the last crossed axis varies fastest; zipped axes
// form one axis whose i-th value is every zipped axis's i-th value.
std::vector<std::vector<std::string>> AxisCombinations(const SweepSpec& spec) {
  const std::size_t n = spec.axes.size();
  std::vector<std::vector<std::size_t>> groups;  // axis indices advancing together
  std::vector<std::size_t> zipped;
  for (std::size_t a = 0; a < n; ++a) {
    const bool in_zip =
        std::find(spec.zip.begin(), spec.zip.end(), spec.axes[a].key) != spec.zip.end();
    if (in_zip) {
      if (zipped.empty()) groups.push_back({});  // the zip group sits where its first axis is
      zipped.push_back(a);
      continue;
    }
    groups.push_back({a});
  }
  for (auto& g : groups) {
    if (g.empty()) g = zipped;
  }
  std::vector<std::vector<std::string>> combos{std::vector<std::string>(n)};
  for (const auto& group : groups) {
    std::vector<std::vector<std::string>> next;
    const std::size_t length = spec.axes[group.front()].values.size();
    for (const auto& partial : combos) {
      for (std::size_t i = 0; i < length; ++i) {
        std::vector<std::string> combo = partial;
        for (std::size_t a : group) combo[a] = spec.axes[a].values[i];
        next.push_back(combo);
      }
    }
    combos = next;
  }
  return combos;
}

// `values[a]` as the override that sets axis a.
std::string AxisOverride(const SweepSpec& spec, const std::vector<std::string>& values,
                         std::size_t a) {
  return spec.axes[a].key + "=" + values[a];
}

// The first axis whose value alone `fails`, as "set.KEY".
std::optional<std::string> AxisRefusedAlone(
    const SweepSpec& spec, const std::vector<std::string>& values,
    const std::function<bool(const std::vector<std::string>&)>& fails) {
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    if (fails({AxisOverride(spec, values, a)})) return "set." + spec.axes[a].key;
  }
  return std::nullopt;
}

// The first axis without whose value the other axes' values, on top of `base`, no longer `fail`
// (values refused only together), as "set.KEY".
std::optional<std::string> AxisRefusedWithTheRest(
    const SweepSpec& spec, const std::vector<std::string>& values,
    const std::vector<std::string>& base,
    const std::function<bool(const std::vector<std::string>&)>& fails) {
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    std::vector<std::string> without = base;
    for (std::size_t b = 0; b < spec.axes.size(); ++b) {
      if (b != a) without.push_back(AxisOverride(spec, values, b));
    }
    if (!fails(without)) return "set." + spec.axes[a].key;
  }
  return std::nullopt;
}

// The world's first spawn pose (worlds/README.md), as --set overrides; none if it has none.
std::vector<std::string> SpawnOverrides(const std::filesystem::path& world) {
  sim::MjModelPtr model;
  try {
    model = sim::LoadModelFromFile(world.string());
  } catch (const sim::OutOfMemory&) {
    throw;  // not the file's fault: said as such
  } catch (const std::exception&) {
    return {};  // the run reports the compile error with its full context
  }
  // A malformed spawn_0 was skipped here: with the experiment's own robot.spawn the cell then ran
  // there, in a world that named another spot, without a word (s38).
  if (const auto problem = sim::WorldSpawnProblem(model.get(), 0)) {
    throw sim::ConfigError(world.string(), "spawn_0",
                           "the sweep places the robot here: " + *problem);
  }
  const std::optional<std::array<double, 3>> spawn = sim::WorldSpawn(model.get(), 0);
  if (!spawn) return {};
  const auto& data = *spawn;
  const auto text = [](double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), "%.17g", v);
    return std::string(buffer);
  };
  return {"robot.spawn.x_m=" + text(data[0]), "robot.spawn.y_m=" + text(data[1]),
          "robot.spawn.theta_deg=" + text(data[2])};
}

bool SetsSpawn(const SweepSpec& spec) {
  for (const auto& axis : spec.axes) {
    if (axis.key.rfind("robot.spawn", 0) == 0) return true;
  }
  return false;
}

// The sweep field whose value alone makes the base experiment fail to load ("set.KEY",
// "worlds", "seeds"), so the error names what to fix in the sweep file.
std::string CulpritField(const SweepSpec& spec, const SweepCell& cell,
                         const std::vector<std::string>& profile_lines) {
  const auto fails = [&](const std::vector<std::string>& overrides) {
    try {
      eval::CheckProtocolOptions(sim::LoadExperimentConfig(cell.experiment, overrides));
      return false;
    } catch (const sim::ConfigError&) {
      return true;
    }
  };
  if (auto axis = AxisRefusedAlone(spec, cell.values, fails)) return *axis;
  if (!cell.world.empty() && fails({cell.overrides.front()})) return "worlds";
  if (!profile_lines.empty() && fails(profile_lines)) return "profiles (" + cell.profile + ")";
  return "experiment";
}

// The sweep field that set what a cell's scene check refused: for the spawn, a spawn axis, else a
// profile's spawn line, else `worlds` (its spawn_0); for the world, `worlds`, else a profile's
// world= line; else the experiment (its own world and spawn).
std::string SceneCulprit(const SweepSpec& spec, const SweepCell& cell,
                         const std::vector<std::string>& profile_lines, bool spawn) {
  const std::string key = spawn ? "robot.spawn" : "world";
  if (spawn) {
    for (const auto& axis : spec.axes) {
      if (axis.key.rfind(key, 0) == 0) return "set." + axis.key;
    }
  }
  for (const std::string& line : profile_lines) {
    if (line.rfind(key, 0) == 0) return "profiles (" + cell.profile + ")";
  }
  if (!cell.world.empty()) return "worlds";
  return "experiment";
}

// The sweep field that set what a cell's controller-target check refused (`set_by`, the keys the
// problem depends on): an axis over one of them (or a mapping holding one), else a profile line
// setting one, else `worlds` when the world or its spawn_0 is among them, else the experiment.
std::string TargetCulprit(const SweepSpec& spec, const SweepCell& cell,
                          const std::vector<std::string>& profile_lines,
                          const std::vector<std::string>& set_by) {
  const auto sets = [&](const std::string& written) {
    const std::string key = sim::CanonicalKeyPath(written);
    for (const std::string& k : set_by) {
      if (key == k || key.rfind(k + ".", 0) == 0 || k.rfind(key + ".", 0) == 0) return true;
    }
    return false;
  };
  for (const auto& axis : spec.axes) {
    if (sets(axis.key)) return "set." + axis.key;
  }
  for (const std::string& line : profile_lines) {
    if (sets(line.substr(0, line.find('=')))) return "profiles (" + cell.profile + ")";
  }
  if (!cell.world.empty() && (sets("world") || sets("robot.spawn"))) return "worlds";
  return "experiment";
}

// The sweep field to blame for a cell that `check`, a check of the cell's config alone, refuses:
// the first axis with whose value alone the experiment is refused, else the first axis without
// whose value the cell passes (values refused only together: an estimator that needs the gyro and
// the gyro turned off), else a profile, else `worlds`, else the experiment.
std::string ConfigCheckCulprit(const SweepSpec& spec, const SweepCell& cell,
                               const std::vector<std::string>& world_overrides,
                               const std::vector<std::string>& profile_lines,
                               const std::function<void(const sim::ExperimentConfig&)>& check) {
  const auto fails = [&](const std::vector<std::string>& overrides) {
    try {
      check(sim::LoadExperimentConfig(cell.experiment, overrides));
      return false;
    } catch (const sim::ConfigError&) {
      return true;
    }
  };
  if (auto axis = AxisRefusedAlone(spec, cell.values, fails)) return *axis;
  std::vector<std::string> base = world_overrides;
  base.insert(base.end(), profile_lines.begin(), profile_lines.end());
  if (auto axis = AxisRefusedWithTheRest(spec, cell.values, base, fails)) return *axis;
  if (!profile_lines.empty() && fails(profile_lines)) return "profiles (" + cell.profile + ")";
  if (!cell.world.empty() && fails(world_overrides)) return "worlds";
  return "experiment";
}

// The sonar-net weights, plug-in libraries and the protocol's other worlds (seed 000's later
// rooms) a run of `config` reads, those that exist (a missing one is refused by the run, naming
// its field).
std::vector<std::filesystem::path> FilesReadBesidesTheWorld(const sim::ExperimentConfig& config) {
  // A sweep of seed000_rooms.yaml resumed after a later room's world was edited kept the old
  // room's results: only the first room, the experiment's world, was in the cell's id.
  std::vector<std::filesystem::path> files = ProtocolOtherWorlds(config);
  const perception::SonarExplorerOptions& explorer = config.controller.sonar_explorer;
  if (config.controller.type == "sonar_explorer" && explorer.sonar_model == "net") {
    const std::filesystem::path weights = explorer.weights_file;
    files.push_back(weights.is_relative() ? sim::DataRoot() / weights : weights);
  }
  for (const std::filesystem::path& library : config.plugins) files.push_back(library);
  std::erase_if(files, [](const auto& file) { return !perception::IsRegularFile(file); });
  return files;
}

// The resolved config with the world named by its contents rather than its path: a cell's id is
// the same wherever the sweep folder (and the worlds generated into it) lies.
std::string IdentityText(const sim::ExperimentConfig& config,
                         const std::vector<std::pair<std::filesystem::path, std::string>>& read) {
  std::string text = sim::ExperimentConfigToYaml(config);
  const std::string world_id = "world-content-" + WorldContentHash(config.world_path);
  for (const std::string& path : {config.world_path.string(), config.world}) {
    if (path.empty()) continue;
    for (std::size_t at = text.find(path); at != std::string::npos;
         at = text.find(path, at + world_id.size())) {
      text.replace(at, path.size(), world_id);
    }
  }
  // Files the run reads besides the world, by content too: a sweep resumed after its sonar-net
  // weights were retrained into the same file (or a plug-in rebuilt) kept every finished cell's
  // results of the old network beside new cells of the new one, without a word.
  // By content alone: the weights' absolute path (the data root) differs between checkouts.
  for (const auto& [file, hash] : read) text += "\n-- read-file-content-" + hash;
  return text;
}

template <typename T>
bool HasRepeats(const std::vector<T>& items) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    for (std::size_t j = i + 1; j < items.size(); ++j) {
      if (items[i] == items[j]) return true;
    }
  }
  return false;
}

// The field that makes cell `b` repeat cell `a`, and the two values that resolve alike: the first
// of the sweep's axes on which the two cells differ. Judged by the lists' texts alone, a repeat of
// values written apart (duration_s: [5, 5.0], a world and its copy) was blamed on `set` without
// saying which values.
std::pair<std::string, std::string> RepeatedField(const SweepSpec& spec, const SweepCell& a,
                                                  const SweepCell& b) {
  const auto alike = [](const std::string& x, const std::string& y) {
    return "'" + y + "' and '" + x + "' resolve alike";
  };
  if (a.experiment != b.experiment) return {"experiment", alike(a.experiment, b.experiment)};
  if (a.world != b.world) {
    return {"worlds", "'" + b.world + "' and '" + a.world + "' hold the same world"};
  }
  if (a.profile != b.profile) return {"profiles", alike(a.profile, b.profile)};
  for (std::size_t k = 0; k < spec.axes.size() && k < a.values.size(); ++k) {
    if (a.values[k] != b.values[k]) {
      return {"set." + spec.axes[k].key, alike(a.values[k], b.values[k])};
    }
  }
  // Cells alike in every field: an entry given twice in one list.
  const std::string twice = "an entry given twice";
  if (HasRepeats(spec.seeds)) return {"seeds", "seed " + std::to_string(b.seed) + " given twice"};
  if (HasRepeats(spec.experiments)) return {"experiment", twice};
  if (HasRepeats(spec.world_files)) return {"worlds", twice};
  if (!b.family.empty()) {  // two {family, seed} entries that draw the same world
    return {"worlds", "'" + b.world + "' drawn by two entries of family " + b.family};
  }
  if (HasRepeats(spec.profiles)) return {"profiles", twice};
  for (const auto& axis : spec.axes) {
    if (HasRepeats(axis.values)) return {"set." + axis.key, twice};
  }
  return {"set", twice};
}

}  // namespace

std::string StableHash(const std::string& text) {
  char hex[17];
  std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(Fnv1a64(text)));
  return hex;
}

namespace {

struct ProfileLine {
  int number = 0;    // 1-based, in the file
  std::string text;  // "key.path=value"
  std::string key;   // the key path it sets (sim::CanonicalKeyPath of the written one)
};

// The --set lines of a profile file with their line numbers.
std::vector<ProfileLine> ReadProfileLines(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw sim::ConfigError(path.string(), "", "cannot read the profile");
  std::vector<ProfileLine> lines;
  std::map<std::string, std::pair<int, std::string>> key_lines;  // key -> line, key as written
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    // A UTF-8 byte-order mark (an editor's "UTF-8 with BOM") was read as part of the first key:
    // "\xEF\xBB\xBFsensors: unknown key", blamed on the experiment.
    if (number == 1) perception::DropUtf8ByteOrderMark(line);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    const auto start = line.find_first_not_of(' ');
    if (start == std::string::npos || line[start] == '#') continue;
    line = line.substr(start);
    const auto eq = line.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw sim::ConfigError(path.string(), "line " + std::to_string(number),
                             "expected key.path=value");
    }
    // A key set twice in one profile silently took the second value; an experiment refuses a
    // YAML key given twice.
    std::string key = line.substr(0, eq);
    while (!key.empty() && key.back() == ' ') key.pop_back();
    // By the key the line sets: sensors.laser.sigma_m and range_noise_sigma_m are one setting.
    const std::string canonical = sim::CanonicalKeyPath(key);
    if (const auto [first, inserted] = key_lines.emplace(canonical, std::pair{number, key});
        !inserted) {
      const auto& [first_number, first_key] = first->second;
      throw sim::ConfigError(path.string(), "line " + std::to_string(number),
                             key + ": already set on line " + std::to_string(first_number) +
                                 (first_key == key ? "" : " (as " + first_key + ", the same key)") +
                                 " (one of the two values would be lost): remove one");
    }
    // The line is kept in cells.json, JSON text: other bytes than UTF-8 ended the sweep with
    // nlohmann's "invalid UTF-8 byte", naming neither the profile nor its line.
    if (!sim::IsUtf8(line)) {
      throw sim::ConfigError(path.string(), "line " + std::to_string(number),
                             "not UTF-8 text (a sweep records its lines in cells.json)");
    }
    lines.push_back({number, line, canonical});
  }
  return lines;
}

// Cells apply the world, then the profile's lines, then the set axes and the seed: an axis or
// `seeds` overrides a profile line on purpose (ekf_gyro_gain.yaml sweeps the gain its profiles
// hold), but a profile's `world=` overrode the `worlds` axis, whose labels results.csv and
// summary.csv kept: every cell ran the profile's world, named as another.
bool ProfileOverridesTheWorldsAxis(const SweepSpec& spec, const std::string& key) {
  return key == "world" && (!spec.world_files.empty() || !spec.generated.empty());
}

// "PROFILE: line N" for the first line of `profile` the experiment refuses by itself (just
// "PROFILE" when only lines together are refused).
std::string ProfileCulprit(const std::filesystem::path& experiment,
                           const std::filesystem::path& profile) {
  for (const ProfileLine& line : ReadProfileLines(profile)) {
    try {
      sim::LoadExperimentConfig(experiment, {line.text});
    } catch (const sim::ConfigError&) {
      return profile.string() + ": line " + std::to_string(line.number);
    }
  }
  return profile.string();
}

// The sweep field to blame for a cell's overrides the experiment refuses (a profile's lines, when
// the sweep has profiles, then the axes' values): the first axis whose value alone is refused, else
// the first without whose value the rest load, else the profile (its first line refused alone),
// else "set".
std::string CombinationCulprit(const SweepSpec& spec, const std::filesystem::path& experiment,
                               const std::vector<std::string>& combo,
                               const std::filesystem::path& profile,
                               const std::vector<std::string>& profile_lines) {
  const auto fails = [&](const std::vector<std::string>& overrides) {
    try {
      sim::LoadExperimentConfig(experiment, overrides);
      return false;
    } catch (const sim::ConfigError&) {
      return true;
    }
  };
  if (auto axis = AxisRefusedAlone(spec, combo, fails)) return *axis;
  if (auto axis = AxisRefusedWithTheRest(spec, combo, profile_lines, fails)) return *axis;
  return profile.empty() ? "set" : "profiles: " + ProfileCulprit(experiment, profile);
}

}  // namespace

std::string WorldContentHash(const std::filesystem::path& world) {
  const std::string text = sim::ReadTextFile(world);
  std::string content = text;
  // The files it includes or names (meshes, textures) are part of the world: an edited
  // <include file="walls.xml"/> left the cell's id, so a resumed sweep kept the old wall's results.
  // A world that names none hashes as before.
  const std::filesystem::path dir = world.parent_path();
  std::vector<std::filesystem::path> files;
  try {
    files = sim::ReferencedFiles(text, dir, world.filename().string());
  } catch (const std::runtime_error& e) {  // a FIFO or a device named by file=
    throw sim::ConfigError(world.string(), "", e.what());
  }
  const std::filesystem::path canonical_dir = std::filesystem::weakly_canonical(dir);
  for (const std::filesystem::path& file : files) {
    content +=
        "\n-- " + file.lexically_relative(canonical_dir).string() + "\n" + sim::ReadTextFile(file);
  }
  return StableHash(content);
}

std::string ReadFileContentHash(const std::filesystem::path& file) {
  return file.extension() == ".xml" ? WorldContentHash(file) : StableHash(sim::ReadTextFile(file));
}

std::vector<std::string> ReadProfile(const std::filesystem::path& path) {
  std::vector<std::string> lines;
  for (ProfileLine& line : ReadProfileLines(path)) lines.push_back(std::move(line.text));
  return lines;
}

void CheckSweepOverrides(const SweepSpec& spec) {
  // Each profile's lines as the cells apply them, before the axes' values; one empty set without
  // profiles.
  std::vector<std::pair<std::filesystem::path, std::vector<std::string>>> profiles;
  for (const auto& profile : spec.profiles) {
    std::vector<std::string> lines;
    for (ProfileLine& line : ReadProfileLines(profile)) {
      if (ProfileOverridesTheWorldsAxis(spec, line.key)) {
        throw sim::ConfigError(
            spec.source_file,
            "profiles: " + profile.string() + ": line " + std::to_string(line.number),
            "world: the profile would replace the sweep's worlds in every cell, which "
            "results.csv would still label with the worlds axis: give worlds in the sweep, not "
            "in a profile");
      }
      lines.push_back(std::move(line.text));
    }
    profiles.emplace_back(profile, std::move(lines));
  }
  if (profiles.empty()) profiles.emplace_back();
  const std::vector<std::vector<std::string>> combos = AxisCombinations(spec);
  for (const auto& experiment : spec.experiments) {
    try {
      sim::LoadExperimentConfig(experiment, {});
    } catch (const sim::ConfigError& e) {
      throw sim::ConfigError(spec.source_file, "experiment", e.what());
    }
    // Every combination of the axes' values on top of each profile, as the cells will set them,
    // not each value alone: fields checked against each other (squeeze_clearance_m against
    // front_margin_m) refused an axis whose values are fine beside another axis's (s60), or
    // beside a profile's line (s61; a profile's line fine beside an axis's value alike).
    for (const auto& [profile, lines] : profiles) {
      for (const auto& combo : combos) {
        std::vector<std::string> overrides = lines;
        for (std::size_t a = 0; a < spec.axes.size(); ++a)
          overrides.push_back(AxisOverride(spec, combo, a));
        try {
          sim::LoadExperimentConfig(experiment, overrides);
        } catch (const sim::ConfigError& e) {
          // A profile is named by its file and the first line refused alone (was only
          // "profiles", then the experiment).
          throw sim::ConfigError(spec.source_file,
                                 CombinationCulprit(spec, experiment, combo, profile, lines),
                                 e.what());
        }
      }
    }
  }
}

std::vector<SweepCell> ExpandCells(const SweepSpec& spec, const std::vector<SweepWorld>& worlds) {
  std::vector<SweepWorld> world_axis = worlds;
  if (world_axis.empty()) world_axis.push_back({});  // the experiment's own world
  std::vector<std::pair<std::string, std::vector<std::string>>> profiles;
  for (const auto& p : spec.profiles) {
    // Labelled by stem ("bad"), unless another profile shares it (a/noise.set, b/noise.set): the
    // summary groups by this label, so their runs were pooled into one mean over two profiles.
    const bool stem_shared =
        std::count_if(spec.profiles.begin(), spec.profiles.end(),
                      [&](const auto& other) { return other.stem() == p.stem(); }) > 1;
    profiles.emplace_back(stem_shared ? p.string() : p.stem().string(), ReadProfile(p));
  }
  if (profiles.empty()) profiles.push_back({});
  const std::vector<std::vector<std::string>> combos = AxisCombinations(spec);
  const bool sets_spawn = SetsSpawn(spec);
  std::vector<SweepCell> cells;
  std::map<std::string, int> ids;
  // (experiment, world, robot, spawn) compiled: once per world unless an axis moves the spawn.
  std::set<std::tuple<std::string, std::string, std::string, double, double, double>>
      checked_worlds;
  // One scene per (experiment, world, robot) of the current world, in which every cell's
  // controller targets are checked with the robot placed at its spawn (a scene per spawn held 3 MB
  // each: a 60-value spawn axis 217 MB).
  std::map<std::tuple<std::string, std::string, std::string>, std::unique_ptr<sim::Scene>>
      target_scenes;
  // Each file cells read besides their worlds, hashed once: every cell of a sweep reads the same
  // weights or plug-in (a plug-in is megabytes).
  std::map<std::filesystem::path, std::string> content_hashes;
  const auto content_hash = [&](const std::filesystem::path& file) {
    auto [it, added] = content_hashes.try_emplace(file);
    if (added) it->second = ReadFileContentHash(file);
    return it->second;
  };
  for (const auto& experiment : spec.experiments) {
    for (const SweepWorld& world : world_axis) {
      target_scenes.clear();  // one world's scenes at a time
      std::vector<std::string> world_overrides;
      const std::string world_label = world.label.empty() ? world.path.string() : world.label;
      if (!world.path.empty()) {
        world_overrides.push_back("world=" + sim::YamlTextValue(world.path.string()));
        if (!sets_spawn) {
          for (const std::string& o : SpawnOverrides(world.path)) world_overrides.push_back(o);
        }
      }
      for (const auto& [profile_name, profile_lines] : profiles) {
        for (const auto& combo : combos) {
          std::vector<std::uint64_t> seeds = spec.seeds;
          const bool own_seed = seeds.empty();
          if (own_seed) seeds.push_back(0);
          for (std::uint64_t seed : seeds) {
            SweepCell cell;
            cell.index = static_cast<int>(cells.size());
            cell.experiment = experiment.string();
            cell.world = world_label;
            cell.family = world.family;
            cell.profile = profile_name;
            cell.values = combo;
            cell.overrides = world_overrides;
            for (const auto& line : profile_lines) cell.overrides.push_back(line);
            for (std::size_t a = 0; a < spec.axes.size(); ++a) {
              cell.overrides.push_back(AxisOverride(spec, combo, a));
            }
            if (!own_seed) cell.overrides.push_back("seed=" + std::to_string(seed));
            sim::ExperimentConfig config;
            try {
              config = sim::LoadExperimentConfig(experiment, cell.overrides);
              // The protocol's own options too: a bad one fails here, not in every cell's run.
              CheckProtocolOptions(config);
            } catch (const sim::ConfigError& e) {
              throw sim::ConfigError(spec.source_file, CulpritField(spec, cell, profile_lines),
                                     e.what());
            }
            // A hand-given world that is no MJCF, does not compile with the robot, or puts the
            // spawn inside a box failed only in its own cells, as they ran (failures.csv), where
            // `plywood run` refuses it, exit 2 (s57's left item). Compiled once per experiment,
            // world (from `worlds`, a profile or the experiment's own), robot and spawn: once per
            // world unless an axis moves the spawn; a generated world is the generator's.
            // Then each cell's controller targets (waypoints and square corners the robot can
            // reach, a reach tolerance, wheel motors), which also failed only as the cell ran
            // (s58's left item): they need only the config and the world's scene with the robot
            // placed at the cell's spawn, no sensor, estimator or plug-in.
            if (world.family.empty() && config.protocol == "single") {
              std::unique_ptr<sim::Scene>& scene =
                  target_scenes[{experiment.string(), config.world_path.string(), config.robot}];
              try {
                // A spawn not checked yet is checked in a scene of its own (kept if the world has
                // none yet); the world's scene is then reused for every spawn.
                const bool new_spawn =
                    checked_worlds
                        .insert({experiment.string(), config.world_path.string(), config.robot,
                                 config.spawn.x_m, config.spawn.y_m, config.spawn.theta_deg})
                        .second;
                if (new_spawn || !scene) {
                  std::unique_ptr<sim::Scene> checked = sim::MakeCheckedScene(config);
                  if (!scene) scene = std::move(checked);
                }
              } catch (const sim::SpawnRefused& e) {
                throw sim::ConfigError(spec.source_file,
                                       SceneCulprit(spec, cell, profile_lines, true), e.what());
              } catch (const sim::ConfigError& e) {
                throw sim::ConfigError(spec.source_file,
                                       SceneCulprit(spec, cell, profile_lines, false), e.what());
              }
              scene->PlaceRobot(
                  {config.spawn.x_m, config.spawn.y_m, config.spawn.theta_deg * kDegToRad});
              if (const auto problem = sim::FindControllerTargetProblem(config, *scene)) {
                throw sim::ConfigError(
                    spec.source_file, TargetCulprit(spec, cell, profile_lines, problem->set_by),
                    sim::ConfigError(config.source_file, problem->field, problem->message).what());
              }
            }
            // And what the config asks for without the sensors it reads (a wall follower by a
            // laser turned off, an estimator that needs the gyro without it, `lines:` without the
            // laser), which the runner refuses from the config alone before its first step.
            if (config.protocol == "single") {
              const auto check = [](const sim::ExperimentConfig& c) {
                sim::RequireControllerSensors(c);
                sim::RequireOdometrySensors(c);
              };
              try {
                check(config);
              } catch (const sim::ConfigError& e) {
                throw sim::ConfigError(
                    spec.source_file,
                    ConfigCheckCulprit(spec, cell, world_overrides, profile_lines, check),
                    e.what());
              }
            }
            cell.seed = config.seed;
            cell.robot = config.robot;
            if (world.family.empty())
              cell.world_file = std::filesystem::absolute(config.world_path);
            for (const std::filesystem::path& file : FilesReadBesidesTheWorld(config)) {
              cell.read_files.emplace_back(file, content_hash(file));
            }
            cell.id = StableHash(IdentityText(config, cell.read_files));
            if (const auto first = ids.find(cell.id); first != ids.end()) {
              const auto [field, why] = RepeatedField(spec, cells[first->second], cell);
              throw sim::ConfigError(spec.source_file, field,
                                     "cell " + std::to_string(cell.index) + " repeats cell " +
                                         std::to_string(first->second) +
                                         " (the same resolved config: " + why +
                                         "): remove the repeat");
            }
            ids[cell.id] = cell.index;
            if (!world.label.empty()) {
              // Loaded from where the world is now; run from wherever the sweep folder will be.
              cell.overrides[0] = std::string("world=") + kSweepFolderPrefix + world.label;
            }
            cells.push_back(cell);
          }
        }
      }
    }
  }
  return cells;
}

}  // namespace plywood::eval
