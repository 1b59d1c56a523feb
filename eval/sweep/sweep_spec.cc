#include "eval/sweep/sweep_spec.h"

#include <glob.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include "perception/logs/regular_file.h"
#include "sim/config/config_error.h"
#include "sim/config/decimal_whole_number.h"
#include "sim/config/experiment_config.h"
#include "sim/config/folder_behind_links.h"
#include "sim/config/robot_catalog.h"
#include "sim/config/utf8_text.h"
#include "sim/config/yaml_alias_expansion.h"
#include "sim/config/yaml_document.h"
#include "sim/config/yaml_fields.h"
#include "sim/config/yaml_nul_characters.h"
#include "sim/config/yaml_tags.h"
#include "sim/config/yaml_text_value.h"
#include "sim/world/generator/world_families.h"

namespace plywood::eval {
namespace {

namespace fs = std::filesystem;

// Relative paths resolve against the sweep file's folder, then the data root, like `world:` in an
// experiment.
fs::path ResolveFile(const std::string& text, const fs::path& base_dir,
                     const sim::YamlFields& fields, const std::string& key) {
  const fs::path given(text);
  if (given.is_absolute()) {
    if (!perception::IsRegularFile(given)) fields.Fail(key, "no such file: " + text);
    return given.lexically_normal();
  }
  for (const fs::path& base : {base_dir, sim::DataRoot()}) {
    const fs::path candidate = (base / given).lexically_normal();
    if (perception::IsRegularFile(candidate)) return candidate;
  }
  fields.Fail(key, "no such file: " + text + " (looked in " + base_dir.string() + " and " +
                       sim::DataRoot().string() + ")");
}

bool IsGlob(const std::string& text) { return text.find_first_of("*?[") != std::string::npos; }

std::vector<fs::path> Glob(const fs::path& pattern) {
  glob_t matches{};
  std::vector<fs::path> paths;
  if (glob(pattern.c_str(), 0, nullptr, &matches) == 0) {
    for (std::size_t i = 0; i < matches.gl_pathc; ++i) paths.emplace_back(matches.gl_pathv[i]);
  }
  globfree(&matches);
  std::sort(paths.begin(), paths.end());
  return paths;
}

// Every match must be a regular file, as a file named outright must: a FIFO would be opened (to
// hash it) and waited on for ever, a folder or a device read as garbage.
std::vector<fs::path> OnlyRegularFiles(std::vector<fs::path> found, const std::string& text,
                                       const sim::YamlFields& fields, const std::string& key) {
  for (const fs::path& p : found) {
    if (!perception::IsRegularFile(p)) {
      fields.Fail(key, p.string() + " (matched by " + text +
                           "): not a regular file (a folder or a device?)");
    }
  }
  return found;
}

// A glob matches against the sweep file's folder first, then the data root.
std::vector<fs::path> ResolveGlob(const std::string& text, const fs::path& base_dir,
                                  const sim::YamlFields& fields, const std::string& key) {
  const fs::path given(text);
  if (given.is_absolute()) {
    std::vector<fs::path> found = Glob(given);
    if (found.empty()) fields.Fail(key, "no file matches " + text);
    return OnlyRegularFiles(std::move(found), text, fields, key);
  }
  for (const fs::path& base : {base_dir, sim::DataRoot()}) {
    std::vector<fs::path> found = Glob((base / given).lexically_normal());
    if (!found.empty()) return OnlyRegularFiles(std::move(found), text, fields, key);
  }
  fields.Fail(key, "no file matches " + text + " (looked in " + base_dir.string() + " and " +
                       sim::DataRoot().string() + ")");
}

std::string ScalarText(const YAML::Node& node) {
  if (node.IsScalar()) return node.Scalar();
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

// An axis value as the text of its --set line. A `!!str` tag is kept (`!!str 5`): the text alone
// would read as the number or boolean the tag says it is not, and the key's reader refuses a
// string tagged so where it takes one (the experiment's own rule).
std::string AxisValueText(const YAML::Node& node) {
  if (node.IsScalar() && node.Tag() == "tag:yaml.org,2002:str") {
    return "!!str " + sim::YamlTextValue(node.Scalar());
  }
  return ScalarText(node);
}

void ReadSeeds(const YAML::Node& node, const sim::YamlFields& top, SweepSpec& spec) {
  // Read as an experiment's `seed:` is, so `seeds: [010]` runs seed 10, not 8 (yaml-cpp's octal).
  const auto seed_of = [&](const YAML::Node& n, const std::string& field) -> std::uint64_t {
    const std::string text = ScalarText(n);
    if (n.Tag() == "tag:yaml.org,2002:str") {
      top.Fail(field,
               "the YAML tag '!!str' says a string, but a seed is a whole number (written '" +
                   text + "'): drop the tag");
    }
    const std::optional<std::uint64_t> seed =
        n.IsScalar() ? sim::ParseDecimalWholeNumber(text) : std::nullopt;
    if (seed) return *seed;
    if (n.IsScalar() && text.starts_with('-')) top.Fail(field, "a seed must be >= 0, got " + text);
    top.Fail(field, "expected a whole number in decimal digits (at most 19), got '" + text + "'");
  };
  if (node.IsSequence()) {
    if (node.size() == 0) top.Fail("seeds", "empty list: give at least one seed");
    for (const auto& item : node) spec.seeds.push_back(seed_of(item, "seeds"));
    return;
  }
  if (node.IsMap()) {
    sim::YamlFields range(node, spec.source_file, "seeds");
    if (!range.Has("from") || !range.Has("to")) top.Fail("seeds", "a range needs from: and to:");
    const std::uint64_t from = seed_of(range.Raw("from"), "seeds.from");
    const std::uint64_t to = seed_of(range.Raw("to"), "seeds.to");
    range.Finish();
    if (to < from) top.Fail("seeds.to", "must be >= seeds.from");
    if (to - from >= 100000) top.Fail("seeds", "more than 100000 seeds");
    for (std::uint64_t s = from; s <= to; ++s) spec.seeds.push_back(s);
    return;
  }
  top.Fail("seeds", "expected a list of seeds or {from: A, to: B}");
}

GeneratedWorlds ReadFamily(const YAML::Node& node, const std::string& file,
                           const sim::YamlFields& top) {
  sim::YamlFields family(node, file, "worlds");
  GeneratedWorlds generated;
  if (!family.Has("family")) top.Fail("worlds.family", "missing: name a world generator family");
  family.Get("family", &generated.family);
  try {
    sim::worldgen::FindWorldFamily(generated.family);
  } catch (const std::invalid_argument& e) {
    top.Fail("worlds.family", std::string(e.what()).substr(std::string("family: ").size()));
  }
  if (!family.Has("count")) top.Fail("worlds.count", "missing: how many worlds to generate");
  int count = 0;
  family.Get("count", &count);
  if (count <= 0 || count > 100000) {
    top.Fail("worlds.count", "must be in 1..100000, got " + std::to_string(count));
  }
  generated.count = count;
  family.Get("seed", &generated.seed);
  family.Finish();
  return generated;
}

void ReadWorlds(const YAML::Node& node, const fs::path& base_dir, const sim::YamlFields& top,
                SweepSpec& spec) {
  if (node.IsMap()) {
    spec.generated.push_back(ReadFamily(node, spec.source_file, top));
    return;
  }
  if (!node.IsSequence()) top.Fail("worlds", "expected a list of files/globs or {family: ...}");
  if (node.size() == 0) top.Fail("worlds", "empty list: give at least one world");
  for (const auto& item : node) {
    if (item.IsMap()) {
      spec.generated.push_back(ReadFamily(item, spec.source_file, top));
      continue;
    }
    if (!item.IsScalar()) top.Fail("worlds", "expected a file name, a glob or {family: ...}");
    const std::string text = item.Scalar();
    if (IsGlob(text)) {
      for (const fs::path& p : ResolveGlob(text, base_dir, top, "worlds"))
        spec.world_files.push_back(p);
    } else {
      spec.world_files.push_back(ResolveFile(text, base_dir, top, "worlds"));
    }
  }
}

// A list (or one) of files or globs, each resolved.
std::vector<fs::path> ReadFiles(const YAML::Node& node, const fs::path& base_dir,
                                const sim::YamlFields& top, const std::string& field) {
  std::vector<fs::path> files;
  std::vector<std::string> items;
  if (node.IsScalar()) {
    items.push_back(node.Scalar());
  } else if (node.IsSequence()) {
    if (node.size() == 0) top.Fail(field, "empty list: give at least one file");
    for (const auto& item : node) {
      if (!item.IsScalar()) top.Fail(field, "expected file names or globs");
      items.push_back(item.Scalar());
    }
  } else {
    top.Fail(field, "expected a file name or a list of them");
  }
  for (const std::string& text : items) {
    if (IsGlob(text)) {
      for (const fs::path& p : ResolveGlob(text, base_dir, top, field)) files.push_back(p);
    } else {
      files.push_back(ResolveFile(text, base_dir, top, field));
    }
  }
  return files;
}

// Whether `value`, given to the key path `path`, sets `target` or a key below it (canonical paths).
bool SetsKeyPath(const YAML::Node& value, const std::string& path, const std::string& target) {
  if (!value.IsMap()) return false;
  for (const auto& entry : value) {
    if (!entry.first.IsScalar()) continue;
    const std::string key = sim::CanonicalKeyPath(path + "." + entry.first.Scalar());
    if (key == target || key.starts_with(target + ".")) return true;
    if (target.starts_with(key + ".") && SetsKeyPath(entry.second, key, target)) return true;
  }
  return false;
}

// Cells apply the axes in order, and a value replaces everything under its key: an axis over a
// key inside another axis's mapping (set.controller and set.controller.side_m) lost its values
// to the mapping's when given first, and a mapping's value that set the inner key lost it to the
// inner axis when given after it; results.csv labelled every run with both (s59: the label
// controller.side_m 1 on a run of side_m 2, exit 0).
void RejectAxesInsideAnotherAxis(const SweepAxis& later, const SweepSpec& spec,
                                 const sim::YamlFields& top) {
  const std::string key = sim::CanonicalKeyPath(later.key);
  for (const SweepAxis& earlier : spec.axes) {
    const std::string earlier_key = sim::CanonicalKeyPath(earlier.key);
    if (earlier_key.starts_with(key + ".")) {
      top.Fail("set." + earlier.key,
               "the later axis set." + later.key + " replaces all of " + later.key +
                   " in every cell, so this axis's values never reach a run (results.csv would "
                   "still label the runs with them): give set." +
                   later.key + " first, or vary the key in one axis");
    }
    if (!key.starts_with(earlier_key + ".")) continue;
    for (const std::string& text : earlier.values) {
      YAML::Node value;
      try {
        value = YAML::Load(text);  // a mapping's text as ScalarText wrote it
      } catch (const YAML::Exception&) {
        continue;  // no mapping: the run refuses it
      }
      if (SetsKeyPath(value, earlier_key, key)) {
        top.Fail("set." + earlier.key,
                 "its value '" + text + "' sets " + later.key + ", which the later axis set." +
                     later.key + " replaces in every cell (results.csv would label each run " +
                     "with both values): give the key in one of the two");
      }
    }
  }
}

void ReadAxes(const YAML::Node& node, const sim::YamlFields& top, SweepSpec& spec) {
  if (!node.IsMap()) top.Fail("set", "expected a mapping of key paths to lists of values");
  for (const auto& entry : node) {
    const std::string key = entry.first.as<std::string>();
    const std::string field = "set." + key;
    if (key.empty() || key.front() == '.' || key.back() == '.' ||
        key.find("..") != std::string::npos) {
      top.Fail(field, "not a key path");
    }
    if (key == "seed" || key == "world") {
      top.Fail(field, "use the sweep's own seeds: / worlds: axes");
    }
    // sensors.laser.sigma_m and range_noise_sigma_m are one key: as two axes each cell ran the
    // later one's value while results.csv labelled it with both.
    for (const SweepAxis& earlier : spec.axes) {
      if (sim::CanonicalKeyPath(earlier.key) == sim::CanonicalKeyPath(key)) {
        top.Fail(field, "the same key as set." + earlier.key +
                            " (each cell would run one axis's value under both labels): give one");
      }
    }
    SweepAxis axis{key, {}};
    if (!entry.second.IsSequence()) top.Fail(field, "expected a list of values");
    if (entry.second.size() == 0) top.Fail(field, "empty list: give at least one value");
    for (const auto& value : entry.second) axis.values.push_back(AxisValueText(value));
    RejectAxesInsideAnotherAxis(axis, spec, top);
    spec.axes.push_back(axis);
  }
  if (spec.axes.empty()) top.Fail("set", "empty: give at least one key path");
}

std::vector<std::string> ReadNames(const YAML::Node& node, const sim::YamlFields& top,
                                   const std::string& field) {
  if (!node.IsSequence()) top.Fail(field, "expected a list");
  std::vector<std::string> names;
  for (const auto& item : node) {
    if (!item.IsScalar()) top.Fail(field, "expected a list of names");
    // metrics: [m, m] wrote every summary.csv row of m twice, group_by: [seed, seed] two seed
    // columns: one table counted twice by whatever reads it.
    if (std::find(names.begin(), names.end(), item.Scalar()) != names.end()) {
      top.Fail(field, "'" + item.Scalar() + "' is listed twice: give each once");
    }
    names.push_back(item.Scalar());
  }
  return names;
}

// cells.json and sweep.json hold every path and axis value as JSON text, which must be UTF-8.
void RequireUtf8(const SweepSpec& spec, const sim::YamlFields& top) {
  const auto check = [&](const std::string& field, const std::string& text, bool is_path) {
    if (sim::IsUtf8(text)) return;
    top.Fail(field, std::string(is_path ? "the path '" : "the value '") + text +
                        "' is not UTF-8 text (a sweep records it in cells.json): " +
                        (is_path ? "rename the file" : "write it in UTF-8"));
  };
  for (const fs::path& p : spec.experiments) check("experiment", p.string(), true);
  for (const fs::path& p : spec.profiles) check("profiles", p.string(), true);
  for (const fs::path& p : spec.world_files) check("worlds", p.string(), true);
  for (const SweepAxis& axis : spec.axes) {
    check("set", axis.key, false);
    for (const std::string& value : axis.values) check("set." + axis.key, value, false);
  }
}

// The most cells a sweep may have. Every cell is loaded and checked before the first runs (about
// 1 ms each) and held in memory and cells.json (about 0.5 kB each): six axes of 8 values (262144
// cells) spent minutes and a GB before anything ran, eight axes ran out of memory (s61). 100000
// is also the most seeds a range and the most worlds a family may give.
constexpr long double kMaxSweepCells = 100000;

// The number of cells as the factors multiply (experiment x worlds x profiles x set x seeds, the
// zipped axes once): refused above kMaxSweepCells, naming the field that contributes most.
void RequireCellsWithinTheLimit(const SweepSpec& spec, const sim::YamlFields& top) {
  struct Factor {
    std::string field;
    long double count;
    std::string made_of;  // how the count is made (the set axes' lengths), or empty
  };
  long double worlds = static_cast<long double>(spec.world_files.size());
  for (const GeneratedWorlds& g : spec.generated) worlds += g.count;
  long double combinations = 1;
  std::vector<std::string> lengths;  // of the axes crossed, the zip group once
  bool zip_counted = false;
  for (const SweepAxis& axis : spec.axes) {
    const bool zipped = std::find(spec.zip.begin(), spec.zip.end(), axis.key) != spec.zip.end();
    if (zipped && zip_counted) continue;  // the zip group advances as one axis
    zip_counted = zip_counted || zipped;
    combinations *= static_cast<long double>(axis.values.size());
    lengths.push_back(std::to_string(axis.values.size()));
  }
  std::string crossed;  // "8 x 8": each crossed axis's length
  for (const std::string& length : lengths) crossed += (crossed.empty() ? "" : " x ") + length;
  const std::vector<Factor> factors{
      {"experiment", static_cast<long double>(spec.experiments.size()), ""},
      {"worlds", std::max<long double>(worlds, 1), ""},
      {"profiles", std::max<long double>(static_cast<long double>(spec.profiles.size()), 1), ""},
      {"set", combinations, lengths.size() > 1 ? crossed : ""},
      {"seeds", std::max<long double>(static_cast<long double>(spec.seeds.size()), 1), ""}};
  long double cells = 1;
  for (const Factor& f : factors) cells *= f.count;
  if (cells <= kMaxSweepCells) return;
  const auto count_text = [](long double n) {
    char text[64];
    if (n < 1e18L) {
      std::snprintf(text, sizeof(text), "%.0Lf", n);
    } else {
      std::snprintf(text, sizeof(text), "%.3Lg", n);  // inf for counts past long double
    }
    return std::string(text);
  };
  const Factor* largest = &factors.front();
  std::string product;
  for (const Factor& f : factors) {
    if (f.count > largest->count) largest = &f;
    if (f.count <= 1) continue;
    product += (product.empty() ? "" : " x ") + f.field + " " +
               (f.made_of.empty() ? count_text(f.count) : f.made_of);
  }
  top.Fail(largest->field, "the sweep would have " + count_text(cells) + " cells (" + product +
                               "), more than the limit of " + count_text(kMaxSweepCells) +
                               ": each is loaded and checked before the first runs; split the "
                               "sweep, zip axes that advance together, or give fewer values");
}

}  // namespace

SweepSpec LoadSweepSpec(const fs::path& path) {
  SweepSpec spec;
  spec.source_file = path.string();
  // Checked before opening: opening a FIFO waits for a writer, for ever.
  if (!perception::IsRegularFile(path)) {
    throw sim::ConfigError(path.string(), "", perception::WhyNotARegularFile(path, "sweep file"));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw sim::ConfigError(path.string(), "", "cannot read the sweep file");
  std::stringstream text;
  text << in.rdbuf();
  spec.text = text.str();
  const YAML::Node root = sim::LoadOneYamlDocument(spec.text, path.string());
  if (!root.IsMap()) throw sim::ConfigError(path.string(), "", "expected a mapping");
  sim::RejectAliasExpansion(root, spec.source_file);
  sim::RejectDuplicateKeys(root, spec.source_file);  // a repeated axis would silently win
  sim::RejectNonStandardTags(root, spec.source_file);
  sim::RejectNulCharacters(root, spec.source_file);
  const fs::path base_dir = sim::FolderBehindLinks(path);  // a link's target's folder
  sim::YamlFields top(root, spec.source_file, "");
  spec.name = path.stem().string();
  top.Get("name", &spec.name);
  // The name becomes runs/sweeps/NAME: one plain folder.
  if (spec.name.empty() || spec.name.front() == '.' ||
      spec.name.find_first_not_of(
          "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_.-") !=
          std::string::npos) {
    // Without a name: key the name is the file's stem, which the user never wrote as a name: the
    // line blamed `name` in a file that has none ("my sweep.yaml").
    const std::string from_stem =
        top.Has("name") ? std::string()
                        : " (no name: key, so the file's name; add name: NAME or rename the file)";
    top.Fail("name", "must be a plain folder name (letters, digits, '_', '.', '-'), got '" +
                         spec.name + "'" + from_stem);
  }
  if (!top.Has("experiment")) top.Fail("experiment", "missing: name the base experiment");
  spec.experiments = ReadFiles(top.Raw("experiment"), base_dir, top, "experiment");
  if (top.Has("profiles"))
    spec.profiles = ReadFiles(top.Raw("profiles"), base_dir, top, "profiles");
  if (top.Has("seeds")) ReadSeeds(top.Raw("seeds"), top, spec);
  if (top.Has("worlds")) ReadWorlds(top.Raw("worlds"), base_dir, top, spec);
  if (top.Has("set")) ReadAxes(top.Raw("set"), top, spec);
  if (top.Has("zip")) {
    spec.zip = ReadNames(top.Raw("zip"), top, "zip");
    std::size_t length = 0;
    for (const std::string& key : spec.zip) {
      const auto axis = std::find_if(spec.axes.begin(), spec.axes.end(),
                                     [&](const SweepAxis& a) { return a.key == key; });
      if (axis == spec.axes.end()) top.Fail("zip", "'" + key + "' is not a key of set:");
      if (length != 0 && axis->values.size() != length) {
        top.Fail("zip", "zipped axes need lists of equal length ('" + key + "' has " +
                            std::to_string(axis->values.size()) + ", the first " +
                            std::to_string(length) + ")");
      }
      length = axis->values.size();
    }
  }
  if (top.Has("metrics")) {
    spec.metrics = ReadNames(top.Raw("metrics"), top, "metrics");
    // Without metrics: summary.csv holds every numeric metric; `metrics: []` read as that, the
    // opposite of the empty list written (s57's left item). `zip: []` and `group_by: []` mean
    // what their absence means (nothing zipped, no extra group), so they stay accepted.
    if (spec.metrics.empty()) {
      top.Fail("metrics",
               "empty list: name the metrics to print, summarise and plot, or leave metrics out "
               "(summary.csv then holds every numeric metric)");
    }
  }
  // Every key of a metrics.json is a word: a name with an empty part ('', 'odometry.encoder.')
  // is in no run's, and was refused only after every cell had run (s57).
  for (const std::string& metric : spec.metrics) {
    const std::string dotted = "." + metric + ".";
    if (metric.empty() || dotted.find("..") != std::string::npos) {
      top.Fail("metrics", "'" + metric +
                              "' has an empty key (a metrics.json key path is words joined by "
                              "'.', as odometry.encoder.drift_percent): no run reports it");
    }
  }
  if (top.Has("group_by")) {
    spec.group_by = ReadNames(top.Raw("group_by"), top, "group_by");
    for (const std::string& g : spec.group_by) {
      if (g != "world" && g != "family" && g != "seed") {
        top.Fail("group_by", "unknown column '" + g + "' (known: world, family, seed)");
      }
    }
  }
  top.Finish();
  RequireUtf8(spec, top);
  RequireCellsWithinTheLimit(spec, top);
  return spec;
}

}  // namespace plywood::eval
