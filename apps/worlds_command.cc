#include "apps/worlds_command.h"

#include <charconv>
#include <chrono>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>

#include "apps/command_line.h"
#include "render/world_preview.h"
#include "sim/world/generator/robot_reach.h"
#include "sim/world/generator/world_families.h"
#include "sim/world/generator/world_generator.h"

namespace plywood::apps {
namespace {

constexpr const char* kUsage =
    "usage: plywood worlds generate FAMILY --count N --seed S --out DIR [--pictures] [--quiet] "
    "| plywood worlds list";

// A whole decimal number in [0, max], digits only.
std::optional<std::uint64_t> ParseWhole(const std::string& text, std::uint64_t max) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || ptr != end || value > max) return std::nullopt;
  return value;
}

std::string Required(const CommandLine& line, const std::string& flag) {
  const auto value = line.Value(flag);
  if (!value) {
    throw UsageError{flag +
                     ": missing (plywood worlds generate FAMILY --count N --seed S --out DIR)"};
  }
  return *value;
}

int List() {
  for (const auto& family : sim::worldgen::WorldFamilies()) {
    std::printf("%-9s %s\n", family.name.c_str(), family.description.c_str());
  }
  return 0;
}

}  // namespace

int WorldsCommand(const std::vector<std::string>& args) {
  const CommandLine line(args, {"--count", "--seed", "--out"}, {"--pictures", "--quiet"});
  const auto& positional = line.positional();
  if (positional.size() == 1 && positional[0] == "list") return List();
  if (positional.size() != 2 || positional[0] != "generate") throw UsageError{kUsage};

  sim::worldgen::GenerateWorldsOptions options;
  options.family = positional[1];
  try {
    sim::worldgen::FindWorldFamily(options.family);
  } catch (const std::invalid_argument& e) {
    throw UsageError{std::string("FAMILY") + std::string(e.what()).substr(6)};
  }
  const std::string count = Required(line, "--count");
  const auto n = ParseWhole(count, sim::worldgen::kMaxWorldCount);
  if (!n || *n < 1) {
    throw UsageError{"--count: must be a whole number in [1, " +
                     std::to_string(sim::worldgen::kMaxWorldCount) + "], got '" + count + "'"};
  }
  options.count = static_cast<int>(*n);
  const std::string seed = Required(line, "--seed");
  const auto s = ParseWhole(seed, std::numeric_limits<std::uint64_t>::max());
  if (!s) throw UsageError{"--seed: must be a whole number in [0, 2^64), got '" + seed + "'"};
  options.seed = *s;
  options.out_dir = Required(line, "--out");

  const auto start = std::chrono::steady_clock::now();
  std::vector<sim::worldgen::GeneratedWorldFile> files;
  try {
    files = sim::worldgen::GenerateWorlds(options);
  } catch (const std::invalid_argument& e) {
    throw UsageError{"--" + std::string(e.what())};
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (line.Switch("--pictures")) {
    for (const auto& file : files) {
      render::WriteWorldPreview(file.mjcf, sim::worldgen::LargestRobotReachM(),
                                std::filesystem::path(file.mjcf).replace_extension(".png"));
    }
  }
  if (!line.Switch("--quiet")) {
    std::printf("%d %s world%s (seed %s) in %s: %.1f ms per world\n", options.count,
                options.family.c_str(), options.count == 1 ? "" : "s", seed.c_str(),
                options.out_dir.c_str(), 1000.0 * seconds / options.count);
  }
  return 0;
}

}  // namespace plywood::apps
