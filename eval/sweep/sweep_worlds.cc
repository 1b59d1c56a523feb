#include "eval/sweep/sweep_worlds.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "sim/config/config_error.h"
#include "sim/runner/text_file.h"
#include "sim/world/generator/world_families.h"
#include "sim/world/generator/world_generator.h"

namespace plywood::eval {
namespace {

namespace fs = std::filesystem;

int IndexRows(const fs::path& index) {
  std::ifstream in(index);
  int rows = -1;  // the header
  for (std::string line; std::getline(in, line);) ++rows;
  return rows;
}

// The first file of `fresh` whose bytes `kept` does not hold under the same name, or "".
std::string FirstDifferentFile(const fs::path& fresh, const fs::path& kept) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fresh)) files.push_back(entry.path().filename());
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    if (!fs::is_regular_file(kept / file) ||
        sim::ReadTextFile(kept / file) != sim::ReadTextFile(fresh / file)) {
      return (kept / file).string();
    }
  }
  return "";
}

// Removes the FAMILY-seedS.partial-PID folders beside `dir` whose process is gone: a sweep killed
// while it generated the set leaves one, and the expansions after it, which stage under their own
// PID, left it there for good (s51: 32 worlds beside the whole set after a resume). A PID still
// alive is another sweep's expansion at work and is left alone.
void RemoveStaleStagedSets(const fs::path& dir) {
  const std::string set = dir.filename().string();
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(dir.parent_path(), error)) {
    const auto staged_by = sim::StagedCopyPid(entry.path().filename().string(), set);
    if (!staged_by) continue;
    const pid_t pid = static_cast<pid_t>(*staged_by);
    if (pid != getpid() && kill(pid, 0) != 0 && errno == ESRCH) fs::remove_all(entry.path());
  }
}

// The generator's worlds of one family, written once under OUT/worlds/FAMILY-seedS (into a
// temporary folder renamed at the end, so a killed sweep never leaves half a set). World i does not
// depend on the count, so a larger count only adds worlds. A set already there is made again and
// compared whenever the sweep is expanded: one edited by hand (a resume notices it through
// sweep.json's inputs) is written anew, or its unfinished cells ran the edit under the
// generator's label.
std::vector<SweepWorld> Generated(const SweepSpec& spec, const GeneratedWorlds& generated,
                                  const fs::path& out_dir, bool quiet) {
  try {
    sim::worldgen::FindWorldFamily(generated.family);
  } catch (const std::invalid_argument& e) {
    throw sim::ConfigError(spec.source_file, "worlds.family",
                           std::string(e.what()).substr(std::string("family: ").size()));
  }
  const fs::path dir =
      out_dir / "worlds" / (generated.family + "-seed" + std::to_string(generated.seed));
  {
    const int kept_rows = IndexRows(dir / "index.csv");
    const fs::path partial = sim::StagedTextFilePath(dir);
    RemoveStaleStagedSets(dir);
    fs::remove_all(partial);
    sim::worldgen::GenerateWorldsOptions options;
    options.family = generated.family;
    options.count = std::max(generated.count, kept_rows);
    options.seed = generated.seed;
    options.out_dir = partial;
    try {
      sim::worldgen::GenerateWorlds(options);
    } catch (...) {
      // The staging folder a failed generation (a full disk) emptied is no set a kill left: it
      // stayed beside the sets until the next sweep (s63 fiftieth pass).
      std::error_code ignored;
      fs::remove_all(partial, ignored);
      try {
        throw;
      } catch (const std::invalid_argument& e) {
        throw sim::ConfigError(spec.source_file, "worlds", e.what());
      }
    }
    const bool complete = kept_rows >= generated.count;
    const std::string edited = complete ? FirstDifferentFile(partial, dir) : "";
    if (complete && edited.empty()) {
      fs::remove_all(partial);
    } else {
      if (!edited.empty() && !quiet) {
        std::fprintf(stderr,
                     "plywood sweep: %s is not what the generator writes (edited by hand?): "
                     "writing %s again\n",
                     edited.c_str(), dir.c_str());
      }
      fs::remove_all(dir);
      fs::create_directories(dir.parent_path());
      fs::rename(partial, dir);
    }
  }
  // index.csv lists the worlds in index order; its first column is the MJCF file's name.
  std::vector<SweepWorld> worlds;
  std::ifstream index(dir / "index.csv");
  std::string line;
  std::getline(index, line);  // header
  while (static_cast<int>(worlds.size()) < generated.count && std::getline(index, line)) {
    const std::string file = line.substr(0, line.find(','));
    const fs::path relative = fs::path("worlds") / dir.filename() / file;
    worlds.push_back(
        {fs::absolute(dir / file).lexically_normal(), generated.family, relative.string()});
  }
  if (static_cast<int>(worlds.size()) < generated.count) {
    throw std::runtime_error((dir / "index.csv").string() + ": fewer worlds than generated");
  }
  return worlds;
}

}  // namespace

std::vector<SweepWorld> PrepareSweepWorlds(const SweepSpec& spec, const fs::path& out_dir,
                                           bool quiet) {
  std::vector<SweepWorld> worlds;
  for (const auto& path : spec.world_files) worlds.push_back({path, "", ""});
  for (const auto& generated : spec.generated) {
    for (SweepWorld& w : Generated(spec, generated, out_dir, quiet)) worlds.push_back(std::move(w));
  }
  return worlds;
}

}  // namespace plywood::eval
