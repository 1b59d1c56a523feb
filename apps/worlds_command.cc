// plywood worlds generate FAMILY --count N --seed S --out DIR [--pictures] [--quiet]
// plywood worlds list

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <system_error>

#include "apps/command.h"
#include "apps/decimal_whole_number.h"
#include "apps/interrupt_signals.h"
#include "render/world_preview.h"
#include "sim/config/decimal_whole_number.h"
#include "sim/runner/folder_lock.h"
#include "sim/world/generator/robot_reach.h"
#include "sim/world/generator/world_families.h"
#include "sim/world/generator/world_generator.h"

namespace plywood::apps {

Command AddWorldsCommand(CLI::App& app) {
  struct Flags {
    std::string family;
    int count = 0;
    std::string seed;
    std::string out;
    bool pictures = false;
    bool quiet = false;
  };
  auto flags = std::make_shared<Flags>();
  CLI::App* cli = app.add_subcommand(
      "worlds", "Generate seeded plywood worlds (docs/worlds.md), or list the families");
  cli->require_subcommand(1);
  CLI::App* list = cli->add_subcommand("list", "Print every world family with one line on it");
  CLI::App* generate = cli->add_subcommand(
      "generate",
      "Write COUNT standalone MJCF worlds of FAMILY (NAME.xml, a NAME.json sidecar with the drawn "
      "parameters and spawn poses, index.csv), byte-identical per seed");
  generate
      ->add_option("FAMILY", flags->family,
                   "room, doorways, columns, clutter, stubs, "
                   "corridor, seed001 or office (plywood worlds list)")
      ->required();
  generate->add_option("--count", flags->count, "how many worlds")
      ->type_name("N")
      ->transform(DecimalWholeNumber())
      ->required()
      ->check(CLI::Range(1, sim::worldgen::kMaxWorldCount));
  generate->add_option("--seed", flags->seed, "seed of the draws; world i depends only on it")
      ->type_name("S")
      ->required();
  generate->add_option("--out", flags->out, "output directory (created when missing)")
      ->type_name("DIR")
      ->required();
  generate->add_flag("--pictures", flags->pictures, "also write a top-down PNG of every world");
  generate->add_flag("--quiet", flags->quiet, "print nothing");
  const char* examples =
      "Examples:\n"
      "  plywood worlds list\n"
      "  plywood worlds generate clutter --count 20 --seed 1 --out /tmp/clutter --pictures";
  cli->footer(examples);
  generate->footer(examples);
  list->footer(examples);
  return {
      cli, [flags, list, generate] {
        if (list->parsed()) {
          for (const auto& family : sim::worldgen::WorldFamilies()) {
            std::printf("%-9s %s\n", family.name.c_str(), family.description.c_str());
          }
          return 0;
        }
        if (const auto extras = WordsNotTaken(*generate); !extras.empty()) {
          throw UsageError("worlds generate: unexpected argument '" + extras.front() + "'");
        }
        sim::worldgen::GenerateWorldsOptions options;
        options.family = flags->family;
        try {
          sim::worldgen::FindWorldFamily(options.family);
        } catch (const std::invalid_argument& e) {
          throw UsageError("worlds generate: FAMILY" + std::string(e.what()).substr(6));
        }
        options.count = flags->count;
        // Digits only (CLI11 would wrap "-1" into 2^64 - 1), at most 19 of them: the rule of a
        // sweep's `worlds: {seed}`, so every generated set can be named in a sweep by its seed.
        const std::optional<std::uint64_t> seed = sim::ParseDecimalWholeNumber(flags->seed);
        if (!seed) {
          throw UsageError(
              "worlds generate: --seed: must be a whole number >= 0 in decimal digits, at most 19 "
              "(as a sweep's worlds: seed and a run's seed take), got '" +
              flags->seed + "'");
        }
        options.seed = *seed;
        options.out_dir = flags->out;
        // SIGINT / SIGTERM stop the generation between two files and remove it, then end the
        // process by that signal: killed mid-way, it left worlds without index.csv, and the
        // folder refused the next generation (s63 fiftieth pass).
        InterruptSignals signals;
        options.interrupted = [&signals] { return signals.Received() != 0; };
        // One generation at a time in a folder, pictures included: two at once (another seed or
        // count) both exited 0, one's worlds left unlisted beside the other's index.csv.
        std::error_code not_made;  // GenerateWorlds names why
        std::filesystem::create_directories(options.out_dir, not_made);
        const sim::FolderLock lock(options.out_dir);
        if (lock.busy()) {
          throw UsageError("worlds generate: --out: " + options.out_dir.string() +
                           ": another plywood worlds generate is writing this folder; wait for "
                           "it or choose another folder");
        }
        const auto start = std::chrono::steady_clock::now();
        std::vector<sim::worldgen::GeneratedWorldFile> files;
        try {
          files = sim::worldgen::GenerateWorlds(options);
        } catch (const sim::worldgen::GenerationInterrupted&) {
          signals.DieOfTheReceivedSignal();
          throw;
        } catch (const std::invalid_argument& e) {
          throw UsageError("worlds generate: --" + std::string(e.what()));
        }
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (flags->pictures) {
          try {
            for (const auto& file : files) {
              if (options.interrupted()) throw sim::worldgen::GenerationInterrupted();
              render::WriteWorldPreview(file.mjcf, sim::worldgen::LargestRobotReachM(),
                                        std::filesystem::path(file.mjcf).replace_extension(".png"));
            }
          } catch (...) {
            // A generation whose pictures cannot be written is removed as a whole, as one cut
            // short by a world: its worlds and index.csv without pictures looked finished (s63).
            std::error_code ignored;
            for (const auto& file : files) {
              std::filesystem::remove(file.mjcf, ignored);
              std::filesystem::remove(file.sidecar, ignored);
              std::filesystem::remove(std::filesystem::path(file.mjcf).replace_extension(".png"),
                                      ignored);
            }
            std::filesystem::remove(options.out_dir / "index.csv", ignored);
            signals.DieOfTheReceivedSignal();
            throw;
          }
        }
        signals.DieOfTheReceivedSignal();  // one that came after the last file: the folder is whole
        if (!flags->quiet) {
          std::printf("%d %s world%s (seed %llu) in %s: %.1f ms per world\n", options.count,
                      options.family.c_str(), options.count == 1 ? "" : "s",
                      static_cast<unsigned long long>(options.seed), options.out_dir.c_str(),
                      1000.0 * seconds / options.count);
        }
        return 0;
      }};
}

}  // namespace plywood::apps
