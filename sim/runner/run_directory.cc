#include "sim/runner/run_directory.h"

#include <array>
#include <fstream>
#include <string>
#include <string_view>

#include "sim/config/config_error.h"

namespace plywood::sim {
namespace {

namespace fs = std::filesystem;

// Every file name a run or a protocol writes (docs/run_outputs.md), and the patterns of the ones
// named after something (trajectory.<estimator>.tum, <room>.png, cloud_<name>.png). --force
// removes these and nothing else.
bool IsRunOutputFile(const std::string& name) {
  static constexpr std::array<std::string_view, 25> kNames = {
      "config.yaml",        "metrics.json",       "timing.json",
      "cognitive_map.json", "trajectory.csv",     "walls.csv",
      "laser.log",          "laser_hits.csv",     "laser_scans.csv",
      "lines.csv",          "sonar.csv",          "ir_ring.csv",
      "ir_scanner.csv",     "encoders.csv",       "gyro.csv",
      "bumpers.csv",        "rooms.csv",          "umbmark_runs.csv",
      "snapshot.png",       "occupancy_grid.png", "occupancy_partitions.png",
      "segments.png",       "lines_truth.csv",    "lines_odometry.csv",
      "geometric_map.json"};
  for (std::string_view known : kNames) {
    if (name == known) return true;
  }
  if (name.starts_with("trajectory.") && name.ends_with(".tum")) return true;
  return name.ends_with(".png");  // pictures a protocol names after a room or a cloud
}

// The first entry under `dir` that no run writes, or empty when there is none. Subfolders count as
// run output when everything in them does (UMBmark's before/cw_1/...).
fs::path FirstForeignEntry(const fs::path& dir) {
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    if (entry.is_symlink()) return entry.path();
    if (entry.is_directory()) {
      const fs::path inner = FirstForeignEntry(entry.path());
      if (!inner.empty()) return inner;
      continue;
    }
    if (!entry.is_regular_file() || !IsRunOutputFile(entry.path().filename().string())) {
      return entry.path();
    }
  }
  return {};
}

}  // namespace

bool HoldsPlywoodRun(const fs::path& dir) {
  std::ifstream config(dir / "config.yaml");
  std::string first_line;
  return config && std::getline(config, first_line) && first_line.starts_with("name: ") &&
         fs::is_regular_file(dir / "metrics.json");
}

void PrepareRunDirectory(const fs::path& dir, bool force) {
  std::error_code error;
  const fs::file_status status = fs::status(dir, error);
  if (!fs::exists(status)) {
    // Made now, so an unwritable place is refused before anything is simulated.
    fs::create_directories(dir, error);
    if (error) {
      throw ConfigError(dir.string(), "", "cannot create the output folder: " + error.message());
    }
    fs::remove(dir, error);
    return;
  }
  if (!fs::is_directory(status)) {
    throw ConfigError(dir.string(), "", "exists and is not a directory; choose another --out");
  }
  if (fs::is_empty(dir)) return;
  if (!HoldsPlywoodRun(dir)) {
    throw ConfigError(dir.string(), "",
                      "holds files that are not a Plywood run (no config.yaml and metrics.json); "
                      "choose another --out (--force never deletes them)");
  }
  if (!force) {
    throw ConfigError(dir.string(), "",
                      "already holds an earlier run; add --force to replace it, or choose another "
                      "--out");
  }
  const fs::path foreign = FirstForeignEntry(dir);
  if (!foreign.empty()) {
    throw ConfigError(dir.string(), "",
                      "holds an earlier run and also " + foreign.lexically_relative(dir).string() +
                          ", which no run writes; --force deletes only a run's own files: move it "
                          "away or choose another --out");
  }
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    fs::remove_all(entry.path());
  }
}

}  // namespace plywood::sim
