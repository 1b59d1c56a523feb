#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/world/generator/generated_world.h"

namespace plywood::sim::worldgen {

inline constexpr int kMaxWorldCount = 100000;

// World `index` of `family` generated with `seed`, a pure function of the three: drawn from its
// own random stream (world_rng.h), redrawn from the same stream until the layout fits and free
// spawn poses are found (spawn_placer.h), then turned into the world frame with spawn_0 on the
// origin.
// @throws std::invalid_argument "family: ..." for an unknown family, "index: ..." when negative;
// std::runtime_error when 1000 layouts in a row fail (a generator defect).
GeneratedWorld GenerateWorld(const std::string& family, std::uint64_t seed, int index);

struct GenerateWorldsOptions {
  std::string family;
  int count = 0;
  std::uint64_t seed = 0;
  std::filesystem::path out_dir;
  // Compile each written world with MuJoCo, alone and with the largest robot at every spawn pose
  // (CheckWrittenWorld); a defect is a generator bug and throws.
  bool check_with_mujoco = true;
  // Asked before each world: true stops the generation, which is removed as a whole (a SIGTERM
  // to `plywood worlds generate` left worlds without index.csv, and the folder refused the next
  // generation), and GenerationInterrupted is thrown.
  std::function<bool()> interrupted;

  // @throws std::invalid_argument whose message starts with the field: family, count, out.
  void Validate() const;
};

// Thrown by GenerateWorlds when its options' `interrupted` said so; nothing of it is left.
struct GenerationInterrupted : std::runtime_error {
  GenerationInterrupted() : std::runtime_error("world generation interrupted") {}
};

struct GeneratedWorldFile {
  std::filesystem::path mjcf;
  std::filesystem::path sidecar;
  std::string summary;
};

// Writes worlds 0 .. count-1 into out_dir (created when missing) as NAME.xml (the MJCF, NAME =
// FAMILY_sSEED_IIIII) and NAME.json (the sidecar), and index.csv listing them. The files of
// world i do not depend on count.
// @throws std::invalid_argument naming the field for bad options or an unwritable out_dir;
// std::runtime_error when a written world fails its MuJoCo check.
std::vector<GeneratedWorldFile> GenerateWorlds(const GenerateWorldsOptions& options);

// index.csv: its header line and one world's row.
inline constexpr const char* kWorldIndexHeader =
    "world,sidecar,family,seed,index,attempts,geoms,spawns,closed,rig_coverage\n";
std::string WorldIndexRow(const GeneratedWorld& world);

}  // namespace plywood::sim::worldgen
