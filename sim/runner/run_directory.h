#pragma once

#include <filesystem>
#include <string>

namespace plywood::sim {

// The completion marker of a run directory: written last, just before the directory is renamed
// into place, listing every file of the run with its size in bytes (timing.json, which holds
// wall-clock figures, is left out so that equal runs give equal bytes), and the build ID of the
// plywood program that made it (sim/runner/build_id.h).
inline constexpr const char* kRunCompleteFile = "complete.json";

// Whether `dir` holds an earlier Plywood run, finished or not: its config.yaml starts with
// "name: ", as every run directory's does (the resolved experiment, or the record of a replay),
// and it has a metrics.json.
bool HoldsPlywoodRun(const std::filesystem::path& dir);

// Empty when `dir` holds a finished run: complete.json is there and every file it lists has the
// size it lists. Otherwise why not, as one phrase (and where an interrupted run left its partial
// output). The one check every reader of runs uses: `plywood score`, sweeps (resume and
// --collect), the viewer.
std::string WhyNotAFinishedRun(const std::filesystem::path& dir);

// @throws sim::ConfigError "DIR: not a finished run: WHY" (exit code 2 in the apps) unless `dir`
// holds a finished run.
void RequireFinishedRun(const std::filesystem::path& dir);

// As WhyNotAFinishedRun, but a run a multi-run protocol wrote in a subfolder of its own finished
// run (UMBmark's before/cw_1: no complete.json of its own) counts as finished when the protocol's
// complete.json, one or two levels up, lists its config.yaml (and so, checked, its files). For
// `plywood score`, which scores such runs one by one.
std::string WhyNotAFinishedRunOrPart(const std::filesystem::path& dir);
void RequireFinishedRunOrPart(const std::filesystem::path& dir);

// Writes DIR/complete.json for the files now under `dir` (StagedRunDirectory::Commit does it; tests
// that assemble a run directory by hand use it too).
void WriteCompletionRecord(const std::filesystem::path& dir);

// A run's results are written into a staging folder beside the target, TARGET.partial-PID, and
// renamed into place by Commit() once complete.json is written, so a killed or failed run never
// leaves a directory that reads as a result. Everything about the target is checked by the
// constructor, before anything is simulated:
//   - absent: created empty (so an unwritable place, a name too long or a parent that is a file
//     are refused now); a run that does not finish leaves it empty, which reads as unfinished;
//   - empty: used as it is;
//   - an earlier Plywood run (HoldsPlywoodRun): refused unless `force`; with `force` it stays
//     untouched until Commit(), which swaps the new run in and then deletes the old one;
//   - anything else that is not empty, not a directory, or a run beside files no run writes:
//     refused, even with `force` (a user's own files are never deleted).
// Partial folders of earlier runs into the same target whose process is gone are removed.
// @throws sim::ConfigError naming the target (one line, exit code 2 in the apps) when refused.
class StagedRunDirectory {
 public:
  StagedRunDirectory(const std::filesystem::path& target, bool force);
  // Removes the staging folder (and the empty target it made) unless committed.
  ~StagedRunDirectory();
  StagedRunDirectory(const StagedRunDirectory&) = delete;
  StagedRunDirectory& operator=(const StagedRunDirectory&) = delete;

  // Where the run writes its files.
  const std::filesystem::path& staging() const { return staging_; }

  // Writes complete.json into the staging folder and renames it to the target.
  // @throws sim::ConfigError when the target changed meanwhile (the results stay in staging()).
  void Commit();

 private:
  std::filesystem::path given_;    // the target as the user wrote it, for messages
  std::filesystem::path target_;   // absolute, without a trailing '/'
  std::filesystem::path staging_;  // TARGET.partial-PID
  bool replace_ = false;           // the target holds an earlier run (--force)
  bool created_target_ = false;
  bool committed_ = false;
};

}  // namespace plywood::sim
