#include "apps/sweep_command.h"

#include <unistd.h>

#include <climits>

#include "apps/command_line.h"
#include "eval/sweep/sweep.h"

namespace plywood::apps {
namespace {

std::filesystem::path SelfExecutable() {
  char buffer[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", buffer, sizeof(buffer) - 1);
  if (n <= 0) throw UsageError{"cannot find the plywood binary (/proc/self/exe)"};
  return std::string(buffer, n);
}

}  // namespace

int SweepCommand(const std::vector<std::string>& args) {
  const CommandLine line(
      args, {"--jobs", "--out", "--shard", "--partition", "--max-parallel", "--tasks", "--collect"},
      {"--slurm", "--dry-run", "--bench", "--no-collect", "--quiet"});
  const bool quiet = line.Switch("--quiet");
  if (const auto dir = line.Value("--collect")) {
    if (!line.positional().empty()) throw UsageError{"--collect DIR takes no sweep file"};
    return eval::CollectSweepCommand(*dir, quiet);
  }
  if (line.positional().size() != 1) {
    throw UsageError{
        "usage: plywood sweep SWEEP.yaml [--jobs N] [--out DIR] [--shard I/N] "
        "[--slurm [--partition P] [--max-parallel K] [--dry-run]] | --collect DIR"};
  }
  eval::SweepInvocation invocation;
  invocation.sweep_file = line.positional()[0];
  invocation.out = line.Value("--out").value_or("");
  invocation.jobs = static_cast<int>(line.Number("--jobs").value_or(0));
  if (invocation.jobs < 0) throw UsageError{"--jobs: must be >= 1"};
  if (const auto shard = line.Value("--shard")) {
    int i = -1, n = 0;
    char extra = 0;
    if (std::sscanf(shard->c_str(), "%d/%d%c", &i, &n, &extra) != 2 || n < 1 || i < 0 || i >= n)
      throw UsageError{"--shard: expected I/N with 0 <= I < N, got '" + *shard + "'"};
    invocation.shard_index = i;
    invocation.shard_count = n;
  }
  invocation.collect = !line.Switch("--no-collect");
  invocation.quiet = quiet;
  invocation.slurm = line.Switch("--slurm");
  invocation.dry_run = line.Switch("--dry-run");
  invocation.bench = line.Switch("--bench");
  invocation.slurm_options.partition = line.Value("--partition").value_or("");
  invocation.slurm_options.max_parallel =
      static_cast<int>(line.Number("--max-parallel").value_or(0));
  invocation.slurm_options.tasks = static_cast<int>(line.Number("--tasks").value_or(0));
  invocation.plywood = SelfExecutable();
  return eval::RunSweep(invocation);
}

}  // namespace plywood::apps
