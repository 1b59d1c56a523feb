// plywood sweep SWEEP.yaml [--jobs N] [--out DIR] [--shard I/N] [--no-collect] [--quiet]
//                          [--slurm [--partition P] [--max-parallel K] [--tasks N] [--dry-run]]
//                          [--bench]
// plywood sweep --collect DIR

#include <unistd.h>

#include <climits>
#include <cstdio>
#include <memory>

#include "apps/command.h"
#include "apps/decimal_whole_number.h"
#include "eval/sweep/sweep.h"

namespace plywood::apps {
namespace {

std::filesystem::path SelfExecutable() {
  char buffer[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", buffer, sizeof(buffer) - 1);
  if (n <= 0) throw std::runtime_error("cannot find the plywood binary (/proc/self/exe)");
  return std::string(buffer, static_cast<std::size_t>(n));
}

}  // namespace

Command AddSweepCommand(CLI::App& app) {
  struct Flags {
    std::string sweep;
    std::string collect;
    std::string shard;
    bool no_collect = false;
    eval::SweepInvocation invocation;
  };
  auto flags = std::make_shared<Flags>();
  eval::SweepInvocation& inv = flags->invocation;
  CLI::App* cli = app.add_subcommand(
      "sweep",
      "Run an experiment over worlds x seeds x settings (docs/sweeps.md): one process per run on "
      "every core, resumable after a kill, or as a Slurm job array; results.csv, summary.csv, "
      "plots");
  cli->add_option("SWEEP", flags->sweep, "sweep YAML file (docs/sweeps.md)");
  cli->add_option("--collect", flags->collect,
                  "re-aggregate a sweep directory (results.csv, summary.csv, plots) and stop")
      ->type_name("DIR");
  CLI::Option* jobs = cli->add_option("--jobs", inv.jobs, "runs at once (0: one per core)")
                          ->type_name("N")
                          ->transform(DecimalWholeNumber())
                          ->check(CLI::Range(0, 4096))
                          ->capture_default_str();
  CLI::Option* out = cli->add_option("--out", inv.out, "sweep directory")
                         ->type_name("DIR")
                         ->default_str("runs/sweeps/NAME");
  cli->add_option("--shard", flags->shard,
                  "run only the cells whose index % N == I (what each Slurm task runs)")
      ->type_name("I/N");
  cli->add_flag("--no-collect", flags->no_collect, "run only; leave results.csv etc. to --collect");
  cli->add_flag("--quiet", inv.quiet, "no progress, no table");
  cli->add_flag("--slurm", inv.slurm,
                "write OUT/slurm/sweep.sbatch (a job array of shards) and submit it with sbatch");
  CLI::Option* partition_flag =
      cli->add_option("--partition", inv.slurm_options.partition, "Slurm partition (with --slurm)")
          ->type_name("P");
  CLI::Option* max_parallel =
      cli->add_option("--max-parallel", inv.slurm_options.max_parallel,
                      "at most K array tasks at once (with --slurm; 0: no limit)")
          ->type_name("K")
          ->transform(DecimalWholeNumber())
          ->check(CLI::Range(0, 100000))
          ->capture_default_str();
  CLI::Option* tasks = cli->add_option("--tasks", inv.slurm_options.tasks,
                                       "array tasks (with --slurm; 0: one per run, at most 1000)")
                           ->type_name("N")
                           ->transform(DecimalWholeNumber())
                           ->check(CLI::Range(0, 100000))
                           ->capture_default_str();
  cli->add_flag("--dry-run", inv.dry_run, "with --slurm: write the script, do not submit it");
  cli->add_flag("--bench", inv.bench,
                "run the sweep twice from scratch, with --jobs 1 and with --jobs N, and print the "
                "runs/s of both");
  cli->footer(
      "Examples:\n"
      "  plywood sweep experiments/sweeps/minimal.yaml\n"
      "  plywood sweep experiments/sweeps/lines_generated.yaml --jobs 2 --out /tmp/lines\n"
      "  plywood sweep experiments/sweeps/minimal.yaml --slurm --max-parallel 8\n"
      "  plywood sweep --collect runs/sweeps/minimal");
  return {
      cli, [flags, jobs, out, max_parallel, tasks, partition_flag] {
        eval::SweepInvocation& inv = flags->invocation;
        if (!flags->collect.empty()) {
          if (!flags->sweep.empty()) {
            throw UsageError("sweep: --collect DIR takes no sweep file");
          }
          // --collect re-aggregates DIR in place and runs nothing: a run's flags beside it were
          // dropped without a word (--out X wrote the tables into DIR, not X).
          if (out->count() > 0 || jobs->count() > 0 || !flags->shard.empty() || flags->no_collect ||
              inv.slurm || inv.dry_run || inv.bench || partition_flag->count() > 0 ||
              tasks->count() > 0 || max_parallel->count() > 0) {
            throw UsageError(
                "sweep: --collect DIR writes its tables into DIR and runs nothing: it takes only "
                "--quiet (not --out, --jobs, --shard, --no-collect, --slurm or --bench)");
          }
          return eval::CollectSweepCommand(flags->collect, inv.quiet);
        }
        if (flags->sweep.empty()) {
          throw UsageError("sweep: give a sweep file, or --collect DIR (see plywood sweep --help)");
        }
        if (!flags->shard.empty()) {
          int i = -1, n = 0;
          char extra = 0;
          if (std::sscanf(flags->shard.c_str(), "%d/%d%c", &i, &n, &extra) != 2 || n < 1 || i < 0 ||
              i >= n) {
            throw UsageError("sweep: --shard: expected I/N with 0 <= I < N, got '" + flags->shard +
                             "'");
          }
          inv.shard_index = i;
          inv.shard_count = n;
        }
        // --tasks and --max-parallel without --slurm, or --bench with it, were ignored without
        // a word.
        if (!inv.slurm && (inv.dry_run || partition_flag->count() > 0 || tasks->count() > 0 ||
                           max_parallel->count() > 0)) {
          throw UsageError(
              "sweep: --dry-run, --partition, --tasks and --max-parallel go with --slurm");
        }
        if (inv.bench && (inv.slurm || !flags->shard.empty())) {
          throw UsageError(
              "sweep: --bench runs the whole sweep here, twice; it does not go with --slurm or "
              "--shard");
        }
        // Each array task runs one shard with --jobs 1 (the job script's own flags): --shard or
        // --jobs given with --slurm were dropped without a word, and the script ran every shard.
        if (inv.slurm && (!flags->shard.empty() || jobs->count() > 0)) {
          throw UsageError(
              "sweep: --shard and --jobs do not go with --slurm: each array task runs one shard "
              "with --jobs 1 (set the number of tasks with --tasks)");
        }
        // The name goes into the job script's #SBATCH line: a line break would start a command.
        // An empty name in a list (',', 'a,,b', 'a,') is no partition: sbatch refuses the script
        // only when it is submitted, after the dry run said it was fine. (--partition '' alone
        // means Slurm's default partition, as when it is not given.)
        const std::string& partition = inv.slurm_options.partition;
        const bool empty_name =
            !partition.empty() && (partition.front() == ',' || partition.back() == ',' ||
                                   partition.find(",,") != std::string::npos);
        if (partition.find_first_not_of(
                "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_.-,") !=
                std::string::npos ||
            empty_name) {
          throw UsageError(
              "sweep: --partition: expected Slurm partition names (letters, digits, '_', '.', "
              "'-'; ',' between several), got '" +
              inv.slurm_options.partition + "'");
        }
        inv.collect = !flags->no_collect;
        inv.sweep_file = flags->sweep;
        inv.plywood = SelfExecutable();
        return eval::RunSweep(inv);
      }};
}

}  // namespace plywood::apps
