#pragma once

#include <filesystem>
#include <string>

namespace plywood::eval {

// A sweep as a Slurm job array: task I of N runs `plywood sweep SWEEP --shard I/N --jobs 1`, so
// every cell runs exactly once, in the same run directories as a local sweep.
struct SlurmJobOptions {
  std::string partition;  // empty: the cluster's default
  int max_parallel = 0;   // array throttle (%K); 0: no limit
  int tasks = 0;          // array size; 0: one task per cell, at most 1000
};

// The job script's #SBATCH lines name OUT: a line break in its path would start a command there.
// @throws std::invalid_argument naming --out when the absolute path holds one.
void RequireSlurmSafeFolder(const std::filesystem::path& out_dir);

// Writes OUT/slurm/sweep.sbatch and returns its path and the number of tasks.
// @throws std::invalid_argument as RequireSlurmSafeFolder.
struct SlurmJob {
  std::filesystem::path script;
  int tasks = 0;
};
SlurmJob WriteSlurmJob(const std::filesystem::path& plywood,
                       const std::filesystem::path& sweep_file,
                       const std::filesystem::path& out_dir, int cells,
                       const SlurmJobOptions& options);

// Submits with `sbatch --parsable` and returns the job id.
// @throws std::runtime_error with sbatch's own message when it fails.
std::string SubmitSlurmJob(const SlurmJob& job);

}  // namespace plywood::eval
