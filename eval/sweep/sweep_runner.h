#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "eval/sweep/sweep_cells.h"
#include "eval/sweep/sweep_spec.h"
#include "sim/runner/folder_lock.h"

namespace plywood::eval {

// Where a sweep keeps its files (docs/sweeps.md):
//   OUT/sweep.yaml   the sweep as given          OUT/cells.csv   every cell: index, id, axes
//   OUT/runs/ID/     each finished run, the same bytes as `plywood run` with that config and seed
//   OUT/runs/.partial/  runs in progress (removed on resume)
//   OUT/logs/ID.log  what each run printed      OUT/failures/ID.txt  exit code and error line
//   OUT/results.csv, failures.csv, summary.csv, plots/   (CollectSweep)
struct SweepLayout {
  std::filesystem::path out;
  std::filesystem::path RunDir(const std::string& id) const { return out / "runs" / id; }
  std::filesystem::path PartialRoot() const { return out / "runs" / ".partial"; }
  std::filesystem::path LogFile(const std::string& id) const {
    return out / "logs" / (id + ".log");
  }
  std::filesystem::path FailureFile(const std::string& id) const {
    return out / "failures" / (id + ".txt");
  }
};

struct SweepRunOptions {
  int jobs = 0;  // processes at once; 0: one per core
  int shard_index = 0;
  int shard_count = 1;
  std::filesystem::path plywood;  // the binary that runs each cell (`plywood run`)
  bool quiet = false;
};

struct SweepRunOutcome {
  int cells = 0;         // in this shard
  int already_done = 0;  // finished by an earlier, interrupted sweep
  int ran = 0;
  int failed = 0;
  double wall_s = 0.0;
  double RunsPerSecond() const { return wall_s > 0 ? ran / wall_s : 0.0; }
};

// The cores this process may run on (its CPU affinity: what a Slurm task or taskset gives it).
int UsableCores();

// Cells of shard I/N: those whose index % N == I. Shards partition the cells.
bool InShard(const SweepCell& cell, int shard_index, int shard_count);

// Runs every cell of the shard that has no finished run directory yet, `jobs` at a time, each in
// its own process (`plywood run EXPERIMENT --set ... --out PARTIAL --quiet`), so a crash cannot
// take down the sweep. A run counts as done only once its partial directory is renamed into
// runs/ID, after the process exited 0; a failure lands in failures/ID.txt and the sweep goes on.
// Killing the sweep kills its runs (PR_SET_PDEATHSIG); running it again removes partial directories
// and finishes only what is missing. Progress: done/total, failures, runs/s, ETA on stderr.
SweepRunOutcome RunSweepCells(const std::vector<SweepCell>& cells, const SweepLayout& layout,
                              const SweepRunOptions& options);

// Refuses (sim::ConfigError, before anything is written) an --out that is a file, a folder holding
// anything but this very sweep, or a place that cannot be created; creates it otherwise.
void PrepareSweepFolder(const SweepSpec& spec, const std::filesystem::path& out);

// Held while a sweep (or one shard of it) works in OUT: a second process on the same folder is
// refused with one line, so cells never run twice. A whole sweep locks the folder exclusively;
// shards share it, each shard exclusive. Released when the process ends, however it ends.
class SweepFolderLock {
 public:
  SweepFolderLock(const std::filesystem::path& out, int shard_index, int shard_count, bool quiet);
  ~SweepFolderLock();
  SweepFolderLock(const SweepFolderLock&) = delete;
  SweepFolderLock& operator=(const SweepFolderLock&) = delete;
  SweepFolderLock(SweepFolderLock&&) noexcept = default;  // a moved-from vector is empty
  SweepFolderLock& operator=(SweepFolderLock&&) = delete;

  // Held while `sweep --collect OUT` writes OUT's tables: refused with one line while a whole
  // sweep works there (it collects when its runs end) or another collect writes them, either of
  // which would leave one collect's results.csv beside the other's summary.csv. Shards run on:
  // they write no table, and a collect beside them reports their cells as not run.
  static SweepFolderLock ForCollect(const std::filesystem::path& out);

 private:
  SweepFolderLock() = default;
  std::vector<int> fds_;
  std::unique_ptr<sim::FolderLock> collect_;  // ForCollect's lock on the folder itself
};

// Writes OUT/sweep.yaml and OUT/cells.csv (the manifest that --collect and shards read). Refuses
// (sim::ConfigError) when OUT holds a different sweep.
void WriteSweepManifest(const SweepSpec& spec, const std::vector<SweepCell>& cells,
                        const SweepLayout& layout);

// Empty when `layout.out` holds nothing yet or results this program can resume from; otherwise
// why not, as one phrase: another plywood build ran it (ProgramBuildId differs), or a robot's
// MJCF changed since (sweep.json's robot_models).
std::string WhySweepIsStale(const SweepLayout& layout);

// WorldContentHash of the robot's MJCF in the catalog (models/NAME.xml), or "" when there is no
// such robot or its file cannot be read.
std::string RobotModelHash(const std::string& robot);

// When the folder is stale, says why and removes everything but sweep.yaml and the locks (runs,
// generated worlds, tables), so the sweep starts again; a shard (other shards may be running) is
// refused instead. @throws sim::ConfigError naming the folder for a stale folder of a shard.
void StartAgainIfStale(const SweepLayout& layout, bool shard, bool quiet);

// The cells written by WriteSweepManifest when OUT holds this very sweep (same sweep.yaml bytes)
// made from the same input files (experiments, profiles, worlds: else says so unless `quiet`), so
// Slurm tasks and resumed sweeps need not expand and check every cell again.
std::optional<std::vector<SweepCell>> ReadSweepManifest(const SweepSpec& spec,
                                                        const SweepLayout& layout, bool quiet);

}  // namespace plywood::eval
