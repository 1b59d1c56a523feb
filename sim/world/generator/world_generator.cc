#include "sim/world/generator/world_generator.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "sim/runner/link_to_nowhere.h"
#include "sim/runner/text_file.h"
#include "sim/world/generator/robot_reach.h"
#include "sim/world/generator/spawn_placer.h"
#include "sim/world/generator/world_check.h"
#include "sim/world/generator/world_families.h"
#include "sim/world/generator/world_mjcf_writer.h"
#include "sim/world/generator/world_rng.h"

namespace plywood::sim::worldgen {
namespace {

constexpr int kMaxAttempts = 1000;

// Staged and renamed into place: a failed write (a full disk) never leaves a cut world that a
// later run or a sweep's glob would load.
void WriteText(const std::filesystem::path& path, const std::string& text) {
  try {
    WriteTextFile(path, text);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(std::string("out: ") + e.what());
  }
}

}  // namespace

GeneratedWorld GenerateWorld(const std::string& family_name, std::uint64_t seed, int index) {
  const WorldFamily& family = FindWorldFamily(family_name);
  if (index < 0) throw std::invalid_argument("index: must be >= 0, got " + std::to_string(index));
  WorldRng rng(family.name, seed, static_cast<std::uint64_t>(index));
  SpawnRules rules = DefaultSpawnRules();
  rules.count = family.spawns;
  for (int attempt = 1; attempt <= kMaxAttempts; ++attempt) {
    GeneratedWorld world;
    world.family = family.name;
    world.seed = seed;
    world.index = index;
    world.attempts = attempt;
    const std::optional<double> rotation = family.draw(rng, world);
    if (!rotation || !PlaceSpawns(rng, world, rules)) continue;
    world.Transform(*rotation, Eigen::Vector2d::Zero());
    world.Transform(0.0, -Eigen::Vector2d(world.spawns[0].x_m, world.spawns[0].y_m));
    world.spawns[0].x_m = world.spawns[0].y_m = 0.0;  // exactly, not 1e-17
    return world;
  }
  throw std::runtime_error("world generator: no layout of family " + family.name +
                           " with free spawn poses after " + std::to_string(kMaxAttempts) +
                           " draws (seed " + std::to_string(seed) + ", world " +
                           std::to_string(index) + ")");
}

void GenerateWorldsOptions::Validate() const {
  FindWorldFamily(family);
  if (count < 1 || count > kMaxWorldCount) {
    throw std::invalid_argument("count: must be a whole number in [1, " +
                                std::to_string(kMaxWorldCount) + "], got " + std::to_string(count));
  }
  if (out_dir.empty()) throw std::invalid_argument("out: no output directory given");
}

std::string WorldIndexRow(const GeneratedWorld& world) {
  return world.Name() + ".xml," + world.Name() + ".json," + world.family + "," +
         std::to_string(world.seed) + "," + std::to_string(world.index) + "," +
         std::to_string(world.attempts) + "," + std::to_string(world.geoms.size()) + "," +
         std::to_string(world.spawns.size()) + "," + (world.closed ? "true" : "false") + "," +
         JsonNumber(world.rig_coverage) + "\n";
}

namespace {

// An earlier generation in `dir` (its index.csv lists its worlds) is replaced as a whole, so a
// smaller --count leaves no extra worlds behind; anything else in a non-empty folder is refused,
// so a user's own files are never overwritten or mixed with worlds.
void RemoveEarlierGeneration(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  if (fs::is_empty(dir)) return;
  std::ifstream index(dir / "index.csv");
  std::string line;
  if (!index || !std::getline(index, line) || line + "\n" != kWorldIndexHeader) {
    // An index.csv of the user's own was named as missing (s63).
    throw std::invalid_argument(
        "out: " + dir.string() + " holds files that are not a world generation (" +
        (fs::exists(dir / "index.csv") ? "its index.csv is not a generation's: the first line is "
                                         "not the world index header"
                                       : "no index.csv") +
        "); choose an empty or new folder");
  }
  std::vector<fs::path> generated{dir / "index.csv"};
  for (int line_number = 2; std::getline(index, line); ++line_number) {
    // A generation names its worlds FAMILY_sSEED_IIIII.xml inside the folder; a row naming a path
    // ("../thesis.xml", "/home/me/a.xml": an index edited or copied by hand) removed that file,
    // its .json and its .png outside the folder.
    const std::string name = line.substr(0, line.find(','));
    if (name.size() <= 4 || name.find_first_of("/\\") != std::string::npos || name[0] == '.' ||
        fs::path(name).extension() != ".xml") {
      throw std::invalid_argument(
          "out: " + (dir / "index.csv").string() + ": line " + std::to_string(line_number) +
          ": world '" + name +
          "' is not a world file of the folder (a generation writes FAMILY_sSEED_IIIII.xml), so "
          "this is not an index a generation wrote and nothing was removed; choose another "
          "folder");
    }
    for (const char* extension : {".xml", ".json", ".png"}) {
      generated.push_back(fs::path(dir / name).replace_extension(extension));
    }
  }
  std::vector<fs::path> earlier;  // only the folder's own files are ever removed
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    // A staged copy ("office_s7_00000.png.partial-PID") is what a kill mid-write left of one of
    // the generation's files, so it goes with them.
    const std::string name = entry.path().filename().string();
    const std::size_t infix = name.rfind(".partial-");
    const fs::path staged_of =
        infix == std::string::npos ? fs::path() : dir / name.substr(0, infix);
    const bool staged_copy =
        infix != std::string::npos &&
        StagedCopyPid(name, staged_of.filename().string()).has_value() &&
        std::find(generated.begin(), generated.end(), staged_of) != generated.end();
    if (!staged_copy &&
        std::find(generated.begin(), generated.end(), entry.path()) == generated.end()) {
      throw std::invalid_argument("out: " + dir.string() + " holds " +
                                  entry.path().filename().string() +
                                  ", which no world generation wrote; choose another folder");
    }
    // A generation writes plain files: a folder of one of their names stopped the removal part way
    // (index.csv and the worlds before it gone), "Directory not empty", exit 1 (s63).
    if (!fs::is_regular_file(entry.symlink_status())) {
      throw std::invalid_argument("out: " + dir.string() + " holds " +
                                  entry.path().filename().string() +
                                  ", which is not a file a world generation wrote (" +
                                  (entry.is_symlink() ? "a symbolic link" : "not a plain file") +
                                  "); nothing was removed; choose another folder");
    }
    earlier.push_back(entry.path());
  }
  for (const fs::path& file : earlier) fs::remove(file);
}

}  // namespace

std::vector<GeneratedWorldFile> GenerateWorlds(const GenerateWorldsOptions& options) {
  options.Validate();
  if (const auto nowhere = LinkToNowhere(options.out_dir)) {
    throw std::invalid_argument("out: " + options.out_dir.string() + ": " + *nowhere +
                                "; make that folder or choose another folder");
  }
  std::error_code error;
  std::filesystem::create_directories(options.out_dir, error);
  if (error || !std::filesystem::is_directory(options.out_dir)) {
    throw std::invalid_argument("out: cannot create directory " + options.out_dir.string() +
                                (error ? ": " + error.message() : ": a file is in the way"));
  }
  RemoveEarlierGeneration(options.out_dir);
  std::vector<GeneratedWorldFile> files;
  std::string index = kWorldIndexHeader;
  try {
    for (int i = 0; i < options.count; ++i) {
      if (options.interrupted && options.interrupted()) throw GenerationInterrupted();
      const GeneratedWorld world = GenerateWorld(options.family, options.seed, i);
      GeneratedWorldFile file;
      file.mjcf = options.out_dir / (world.Name() + ".xml");
      file.sidecar = options.out_dir / (world.Name() + ".json");
      file.summary = world.summary;
      files.push_back(file);
      WriteText(file.mjcf, WorldMjcf(world));
      WriteText(file.sidecar, WorldSidecarJson(world));
      if (options.check_with_mujoco) {
        const std::vector<std::string> defects =
            CheckWrittenWorld(file.mjcf, world, LargestRobot());
        if (!defects.empty()) {
          throw std::runtime_error("world generator defect: " + defects.front());
        }
      }
      index += WorldIndexRow(world);
    }
    if (options.interrupted && options.interrupted()) throw GenerationInterrupted();
    WriteText(options.out_dir / "index.csv", index);
  } catch (...) {
    // A generation cut short (a full disk) is removed as a whole: a few worlds without index.csv
    // would look like a smaller generation to a `*.xml` glob and block the next run's folder.
    std::error_code ignored;
    for (const GeneratedWorldFile& file : files) {
      std::filesystem::remove(file.mjcf, ignored);
      std::filesystem::remove(file.sidecar, ignored);
    }
    throw;
  }
  return files;
}

}  // namespace plywood::sim::worldgen
