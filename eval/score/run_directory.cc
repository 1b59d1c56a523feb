#include "eval/score/run_directory.h"

#include <yaml-cpp/yaml.h>

#include "eval/score/csv_table.h"
#include "perception/logs/regular_file.h"
#include "sim/config/config_error.h"
#include "sim/runner/run_directory.h"
#include "sim/world/continuing_faces.h"

namespace plywood::eval {
namespace {

// A `plywood replay` folder is a finished run to the run-folder rules (config.yaml, metrics.json,
// complete.json), but its config.yaml holds the log and the extractor, no world: `score` and
// `view` on one said "config.yaml: world: missing: give the world's MJCF file", or
// "trajectory.csv: missing (the run's ground truth; multi-run protocols keep it in each run's
// subfolder)", as if a run had lost its files (s58).
void RefuseAReplaysFolder(const std::filesystem::path& run_dir) {
  const std::filesystem::path config = run_dir / "config.yaml";
  if (!perception::IsRegularFile(config)) return;
  YAML::Node root;
  try {
    root = YAML::LoadFile(config.string());
  } catch (const YAML::Exception&) {
    return;  // the readers below name what is wrong with it
  }
  if (!root.IsMap() || !root["replay"] || !root["replay"].IsMap()) return;
  const YAML::Node log = root["replay"]["log"];
  throw sim::ConfigError(
      run_dir.string(), "",
      "holds a plywood replay of " + (log && log.IsScalar() ? log.Scalar() : std::string("a log")) +
          " (the lines extracted from a CARMEN log), not a simulated run: it has no world, ground "
          "truth or trajectory to score against or show; give the folder of a plywood run");
}

}  // namespace

std::filesystem::path RunFile(const std::filesystem::path& run_dir, const std::string& name,
                              const std::string& why) {
  // A killed or failed run is never scored; a protocol's finished part (UMBmark's before/cw_1) is.
  sim::RequireFinishedRunOrPart(run_dir);
  RefuseAReplaysFolder(run_dir);
  const std::filesystem::path path = run_dir / name;
  if (!perception::IsRegularFile(path)) {
    throw sim::ConfigError(path.string(), "", "missing (" + why + ")");
  }
  return path;
}

sim::ExperimentConfig LoadRunConfig(const std::filesystem::path& run_dir,
                                    const std::string& command) {
  const std::filesystem::path path =
      RunFile(run_dir, "config.yaml", "every run directory holds its resolved experiment");
  sim::ExperimentConfig config = sim::LoadExperimentConfig(path);
  if (config.protocol != "single") {
    throw sim::ConfigError(path.string(), "protocol",
                           "'" + config.protocol + "' is a multi-run protocol: " + command +
                               " scores the directory of a single run (protocol: single)");
  }
  return config;
}

sim::GroundTruthWalls ReadWallsCsv(const std::filesystem::path& path) {
  const CsvTable table = ReadCsv(path, {.rows_required = false});
  const char* kColumns[] = {"segment", "geom_id", "face", "ax_m", "ay_m", "bx_m", "by_m"};
  for (std::size_t c = 0; c < std::size(kColumns); ++c) {
    if (table.header.size() != std::size(kColumns) || table.header[c] != kColumns[c]) {
      throw sim::ConfigError(table.file + ":" + std::to_string(table.header_line), kColumns[c],
                             "expected the header segment,geom_id,face,ax_m,ay_m,bx_m,by_m");
    }
  }
  sim::GroundTruthWalls walls;
  for (const CsvRow& row : table.rows) {
    if (table.Integer(row, 0, "segment") != static_cast<long>(walls.segments.size())) {
      table.Fail(row, "segment",
                 "expected " + std::to_string(walls.segments.size()) +
                     " (segments are numbered from 0 in order)");
    }
    sim::WallSegment s;
    s.geom_id = static_cast<int>(table.Integer(row, 1, "geom_id"));
    s.face_index = static_cast<int>(table.Integer(row, 2, "face"));
    s.a = {table.Number(row, 3, "ax_m"), table.Number(row, 4, "ay_m")};
    s.b = {table.Number(row, 5, "bx_m"), table.Number(row, 6, "by_m")};
    walls.segments.push_back(s);
  }
  sim::JoinContinuingFaces(&walls);  // scored as the run scored them (sim/world/continuing_faces.h)
  return walls;
}

}  // namespace plywood::eval
