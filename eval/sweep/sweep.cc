#include "eval/sweep/sweep.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <string>
#include <vector>

#include "eval/sweep/sweep_cells.h"
#include "eval/sweep/sweep_results.h"
#include "eval/sweep/sweep_runner.h"
#include "eval/sweep/sweep_spec.h"
#include "eval/sweep/sweep_worlds.h"
#include "sim/config/config_error.h"
#include "sim/config/robot_catalog.h"

namespace plywood::eval {
namespace {

namespace fs = std::filesystem;

// scripts/plot_sweep.py's exit status for a plot it could not write (CANNOT_WRITE there).
constexpr int kPlotCannotBeWritten = 3;

enum class ChildOutput { kAll, kErrorsOnly, kNone };

// Runs `args` (a program's path, then its arguments) and returns its wait status (-1 if it could
// not be started), `output` deciding which of its stdout and stderr reach ours. Not std::system:
// sh's redirections need file descriptors above 10, so under `ulimit -n 10` or less its
// "2>&1" failed ("sh: 1: 1: Invalid argument") and the sweep said "no plots (python3-matplotlib
// not installed)" of an installed one (s65 fifty-fourth pass).
int RunWithoutAShell(const std::vector<std::string>& args, ChildOutput output) {
  std::vector<char*> argv;
  for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  std::fflush(stdout);  // what plywood printed comes before what the child prints
  const pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    if (output != ChildOutput::kAll) {
      const int null = open("/dev/null", O_WRONLY);
      if (null >= 0) {
        dup2(null, STDOUT_FILENO);
        if (output == ChildOutput::kNone) dup2(null, STDERR_FILENO);
        if (null > STDERR_FILENO) close(null);
      }
    }
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return status;
}

// One PNG per chosen metric (scripts/plot_sweep.py, matplotlib); skipped with a note when
// python3-matplotlib is missing, since plots are a convenience, not a result. False when a plot
// could not be written (a full disk).
bool Plot(const fs::path& out_dir, bool quiet) {
  const fs::path script = sim::DataRoot() / "scripts" / "plot_sweep.py";
  if (!fs::is_regular_file(script)) return true;
  if (RunWithoutAShell({"/usr/bin/python3", "-c", "import matplotlib"}, ChildOutput::kNone) != 0) {
    if (!quiet)
      std::fprintf(stderr, "plywood sweep: no plots (python3-matplotlib not installed)\n");
    return true;
  }
  const int status = RunWithoutAShell({"/usr/bin/python3", script.string(), out_dir.string()},
                                      quiet ? ChildOutput::kErrorsOnly : ChildOutput::kAll);
  // A plot the disk would not take was named on one line by the script, which left no cut file:
  // a failed write, not a missing convenience, so the sweep exits 1 (s63 fiftieth pass).
  if (status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == kPlotCannotBeWritten) {
    return false;
  }
  if (status != 0 && !quiet) {
    std::fprintf(stderr, "plywood sweep: plotting failed (see above)\n");
  }
  return true;
}

int Collect(const fs::path& out_dir, bool quiet) {
  const SweepCollectOutcome outcome = CollectSweep(out_dir);
  const bool plotted = Plot(out_dir, quiet);
  if (!quiet) {
    std::printf("%s", outcome.table.c_str());
    std::printf("\n%-12s %d of %d runs finished, %d failed, %d not run", "sweep", outcome.done,
                outcome.cells, outcome.failed, outcome.missing);
    if (outcome.other_build > 0) {
      std::printf(" (%d of them finished by another plywood build: run the sweep to redo them)",
                  outcome.other_build);
    }
    std::printf("\n");
    std::printf("%-12s %s (results.csv, summary.csv, failures.csv, plots/)\n", "results",
                out_dir.c_str());
  }
  return outcome.done == outcome.cells && plotted ? 0 : 1;
}

std::vector<SweepCell> Cells(const SweepSpec& spec, const SweepLayout& layout, bool quiet) {
  if (auto cells = ReadSweepManifest(spec, layout, quiet)) return *cells;
  CheckSweepOverrides(spec);  // before generating worlds: bad input leaves nothing behind
  const std::vector<SweepWorld> worlds = PrepareSweepWorlds(spec, layout.out, quiet);
  std::vector<SweepCell> cells = ExpandCells(spec, worlds);
  WriteSweepManifest(spec, cells, layout);
  return cells;
}

}  // namespace

int RunSweep(const SweepInvocation& invocation) {
  const SweepSpec spec = LoadSweepSpec(invocation.sweep_file);
  const fs::path out =
      invocation.out.empty() ? fs::path("runs") / "sweeps" / spec.name : invocation.out;
  const SweepLayout layout{out};
  if (invocation.slurm) RequireSlurmSafeFolder(out);
  PrepareSweepFolder(spec, out);
  const SweepFolderLock lock(out, invocation.shard_index, invocation.shard_count, invocation.quiet);
  StartAgainIfStale(layout, invocation.shard_count > 1, invocation.quiet);
  const std::vector<SweepCell> cells = Cells(spec, layout, invocation.quiet);
  if (!invocation.quiet && invocation.shard_count == 1) {
    std::fprintf(stderr, "plywood sweep: %s: %zu runs into %s\n", spec.name.c_str(), cells.size(),
                 out.c_str());
  }
  if (invocation.slurm) {
    const SlurmJob job = WriteSlurmJob(invocation.plywood, invocation.sweep_file, out,
                                       static_cast<int>(cells.size()), invocation.slurm_options);
    std::printf("%-12s %s (%d array tasks)\n", "sbatch script", job.script.c_str(), job.tasks);
    if (invocation.dry_run) return 0;
    const std::string id = SubmitSlurmJob(job);
    std::printf("%-12s %s\n%-12s plywood sweep --collect %s\n", "submitted job", id.c_str(), "then",
                out.c_str());
    return 0;
  }
  SweepRunOptions options;
  options.jobs = invocation.jobs;
  options.shard_index = invocation.shard_index;
  options.shard_count = invocation.shard_count;
  options.plywood = invocation.plywood;
  options.quiet = invocation.quiet;
  if (invocation.bench) {
    // Both timings from scratch on the same cells, one process at a time and then `jobs` at once.
    SweepRunOptions serial = options;
    serial.jobs = 1;
    serial.quiet = true;
    SweepRunOptions parallel = options;
    parallel.quiet = true;
    const SweepLayout one{out / "bench-jobs1"}, many{out / "bench-jobsN"};
    fs::remove_all(one.out);
    fs::remove_all(many.out);
    const SweepRunOutcome a = RunSweepCells(cells, one, serial);
    const SweepRunOutcome b = RunSweepCells(cells, many, parallel);
    const int jobs = options.jobs > 0 ? options.jobs : UsableCores();
    std::printf("sweep bench: %d runs of %s\n", a.ran, spec.name.c_str());
    std::printf("%-14s %8.3f runs/s (%.1f s)\n", "--jobs 1", a.RunsPerSecond(), a.wall_s);
    std::printf("%-14s %8.3f runs/s (%.1f s)\n", ("--jobs " + std::to_string(jobs)).c_str(),
                b.RunsPerSecond(), b.wall_s);
    std::printf("%-14s %8.2fx\n", "speed-up",
                a.RunsPerSecond() > 0 ? b.RunsPerSecond() / a.RunsPerSecond() : 0.0);
    return a.failed + b.failed > 0 ? 1 : 0;
  }
  const SweepRunOutcome outcome = RunSweepCells(cells, layout, options);
  // A shard sees only its cells; the others' are collected once every shard is done.
  if (!invocation.collect || invocation.shard_count > 1) return outcome.failed > 0 ? 1 : 0;
  const int collected = Collect(out, invocation.quiet);
  return outcome.failed > 0 ? 1 : collected;
}

int CollectSweepCommand(const fs::path& out_dir, bool quiet) {
  const SweepFolderLock lock = SweepFolderLock::ForCollect(out_dir);
  return Collect(out_dir, quiet);
}

}  // namespace plywood::eval
