#pragma once

#include <filesystem>
#include <string>

#include "eval/sweep/slurm_job.h"

namespace plywood::eval {

// `plywood sweep` (docs/sweeps.md): what to run and how.
struct SweepInvocation {
  std::filesystem::path sweep_file;
  std::filesystem::path out;  // empty: runs/sweeps/<name>
  int jobs = 0;               // 0: one per core
  int shard_index = 0;
  int shard_count = 1;
  bool collect = true;  // results.csv, summary.csv, plots after running
  bool quiet = false;
  bool slurm = false;  // write (and unless dry_run, submit) a Slurm job array instead
  bool dry_run = false;
  SlurmJobOptions slurm_options;
  bool bench = false;             // time the sweep with --jobs 1 and with `jobs`, print both
  std::filesystem::path plywood;  // the binary that runs each cell
};

// Runs (or submits) a sweep; returns the exit code: 0 when every cell finished, 1 when some failed.
// @throws sim::ConfigError for a bad sweep file, before anything runs.
int RunSweep(const SweepInvocation& invocation);

// `plywood sweep --collect DIR`: re-aggregates whatever has finished; prints the summary table.
// Returns 0 when every cell finished, 1 otherwise.
int CollectSweepCommand(const std::filesystem::path& out_dir, bool quiet);

}  // namespace plywood::eval
