#include "eval/sweep/sweep_runner.h"

#include <fcntl.h>
#include <sched.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <thread>

#include "eval/sweep/sweep_csv.h"
#include "eval/sweep/sweep_meta.h"
#include "perception/logs/regular_file.h"
#include "sim/config/config_error.h"
#include "sim/config/robot_catalog.h"
#include "sim/config/yaml_text_value.h"
#include "sim/runner/build_id.h"
#include "sim/runner/folder_lock.h"
#include "sim/runner/link_to_nowhere.h"
#include "sim/runner/out_of_memory.h"
#include "sim/runner/run_directory.h"
#include "sim/runner/text_file.h"
#include "sim/world/generator/world_families.h"

namespace plywood::eval {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The last line a failed run printed that says what went wrong ("plywood: ..."), else its last
// non-empty line.
std::string ErrorLine(const fs::path& log) {
  std::istringstream lines(sim::ReadTextFile(log));
  std::string last, last_plywood;
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    last = line;
    if (line.rfind("plywood:", 0) == 0) last_plywood = line;
  }
  return last_plywood.empty() ? last : last_plywood;
}

// Starts `plywood run` for one cell with its output in `partial` and its stdout/stderr in `log`.
// Returns its pid, or -1 (errno set) when no process could be made.
pid_t StartRun(const SweepCell& cell, const fs::path& plywood, const fs::path& partial,
               const fs::path& log, const fs::path& sweep_folder) {
  std::vector<std::string> args{plywood.string(), "run",    cell.experiment, "--out",
                                partial.string(), "--quiet"};
  const std::string world_in_sweep = std::string("world=") + kSweepFolderPrefix;
  for (const std::string& o : cell.overrides) {
    args.push_back("--set");
    args.push_back(o.starts_with(world_in_sweep)
                       ? "world=" + sim::YamlTextValue((fs::absolute(sweep_folder) /
                                                        o.substr(world_in_sweep.size()))
                                                           .lexically_normal()
                                                           .string())
                       : o);
  }
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid != 0) return pid;  // -1 with errno when no process could be made
  // The child: dies with the sweep, so a killed sweep leaves no run writing behind its back.
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(127);
  // The sweep runs processes side by side, one per core: Mesa's software renderer (snapshots)
  // would otherwise start a thread per core in every run and oversubscribe the machine.
  setenv("LP_NUM_THREADS", "1", 0);
  const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);  // the umask decides
  if (fd >= 0) {
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    close(fd);
  }
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  execv(argv[0], argv.data());
  std::fprintf(stderr, "plywood: cannot run %s\n", argv[0]);
  _exit(127);
}

class Progress {
 public:
  Progress(int total, int done, bool quiet)
      : total_(total), done_at_start_(done), quiet_(quiet), terminal_(isatty(STDERR_FILENO)) {}

  void Report(int done, int failed, bool final) {
    if (quiet_) return;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    if (!final && !terminal_ && elapsed - last_print_s_ < 5.0) return;
    last_print_s_ = elapsed;
    const int ran = done + failed - done_at_start_;
    const double rate = elapsed > 0 ? ran / elapsed : 0.0;
    const int left = total_ - done - failed;
    char eta[32] = "-";
    if (rate > 0 && left > 0) std::snprintf(eta, sizeof(eta), "%.0f s", left / rate);
    std::fprintf(stderr, "%splywood sweep: %d/%d done, %d failed, %.2f runs/s, ETA %s%s",
                 terminal_ ? "\r" : "", done, total_, failed, rate, eta,
                 terminal_ && !final ? "   " : "\n");
    std::fflush(stderr);
  }

 private:
  int total_;
  int done_at_start_;
  bool quiet_;
  bool terminal_;
  Clock::time_point start_ = Clock::now();
  double last_print_s_ = -1e9;
};

// The hash of every file the cells are made from, by path.
std::map<std::string, std::string> InputHashes(const SweepSpec& spec) {
  std::map<std::string, std::string> hashes;
  for (const auto* files : {&spec.experiments, &spec.profiles}) {
    for (const fs::path& file : *files) hashes[file.string()] = StableHash(sim::ReadTextFile(file));
  }
  for (const fs::path& world : spec.world_files) hashes[world.string()] = WorldContentHash(world);
  return hashes;
}

}  // namespace

std::string RobotModelHash(const std::string& robot) {
  try {
    return WorldContentHash(sim::FindRobot(robot).mjcf);  // the file and any it names (meshes)
  } catch (const std::exception&) {
    return "";  // not a robot of this catalog, or its file cannot be read
  }
}

namespace {

// Opens a lock file for flock, made when missing. Its mode is the umask's (0666 before it), as
// every file a sweep writes: one a teammate's sweep made 0644 under umask 002 could not be opened
// for writing, and the sweep ran unlocked without a word. flock needs no write access, so a lock
// file that is read-only to us is opened for reading.
int OpenLockFile(const fs::path& file, bool create) {
  int fd = open(file.c_str(), O_RDWR | O_CLOEXEC | (create ? O_CREAT : 0), 0666);
  if (fd < 0 && errno == EACCES) fd = open(file.c_str(), O_RDONLY | O_CLOEXEC);
  return fd;
}

// Whether a `sweep --collect` holds `out` (the folder lock only collects take): what a sweep
// refused beside it names. Tried and let go at once; flock has no query.
bool ACollectWrites(const fs::path& out) { return sim::FolderLock(out).busy(); }

}  // namespace

SweepFolderLock::SweepFolderLock(const fs::path& out, int shard_index, int shard_count,
                                 bool quiet) {
  const auto take = [&](const fs::path& file, int how) {
    const int fd = OpenLockFile(file, true);
    if (fd < 0) return;
    fds_.push_back(fd);
    if (flock(fd, how | LOCK_NB) == 0) return;
    if (errno == EWOULDBLOCK) {
      // A collect holds sweep.lock shared too: "another sweep is running" named a sweep that was
      // not.
      throw sim::ConfigError(out.string(), "",
                             ACollectWrites(out)
                                 ? "a plywood sweep --collect is writing this folder's tables; "
                                   "wait for it"
                                 : "another plywood sweep is running in this folder; wait for it "
                                   "or choose another --out");
    }
    // Some network file systems have no flock: run unlocked rather than not at all.
    if (!quiet)
      std::fprintf(stderr, "plywood sweep: cannot lock %s; running unlocked\n", file.c_str());
  };
  // A whole sweep excludes everything else; shards (Slurm tasks) share the folder but each shard
  // runs once at a time.
  take(out / "sweep.lock", shard_count > 1 ? LOCK_SH : LOCK_EX);
  if (shard_count > 1) {
    take(out / ("shard-" + std::to_string(shard_index) + "-of-" + std::to_string(shard_count) +
                ".lock"),
         LOCK_EX);
  }
}

SweepFolderLock SweepFolderLock::ForCollect(const fs::path& out) {
  SweepFolderLock lock;
  // Shared on sweep.lock, which a whole sweep holds exclusively and shards shared; nothing to
  // lock when it is missing, as no sweep ever ran there (the collect then says what OUT is).
  if (const int fd = OpenLockFile(out / "sweep.lock", false); fd >= 0) {
    lock.fds_.push_back(fd);
    if (flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK) {
      throw sim::ConfigError(out.string(), "",
                             "a plywood sweep is running in this folder and collects its results "
                             "when its runs end; wait for it");
    }
  }
  // Exclusive on the folder itself, which only collects lock: one collect at a time.
  lock.collect_ = std::make_unique<sim::FolderLock>(out);
  if (lock.collect_->busy()) {
    throw sim::ConfigError(out.string(), "",
                           "another plywood sweep --collect is writing this folder's tables; "
                           "wait for it");
  }
  return lock;
}

SweepFolderLock::~SweepFolderLock() {
  for (int fd : fds_) close(fd);
}

namespace {

// Whether `text` is a non-empty run of decimal digits (a seed).
bool AllDigits(std::string_view text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Whether `name` is `file` or a staged copy of it that a kill left (sim::WriteTextFile writes
// FILE.partial-PID and renames it).
bool IsFileOrItsStagedCopy(const std::string& name, const std::string& file) {
  return name == file || sim::StagedCopyPid(name, file).has_value();
}

// Whether `worlds` holds only generator sets as a sweep writes them: FAMILY-seedS folders, and the
// FAMILY-seedS.partial-PID a kill during the generation left.
bool HoldsOnlyGeneratedSets(const fs::path& worlds) {
  for (const auto& entry : fs::directory_iterator(worlds)) {
    if (!entry.is_directory() || entry.is_symlink()) return false;
    std::string name = entry.path().filename().string();
    if (const auto staged = name.find(".partial-"); staged != std::string::npos) {
      if (!sim::StagedCopyPid(name, std::string_view(name).substr(0, staged))) return false;
      name.resize(staged);
    }
    const auto seed = name.rfind("-seed");
    if (seed == std::string::npos || !AllDigits(std::string_view(name).substr(seed + 5))) {
      return false;
    }
    try {
      sim::worldgen::FindWorldFamily(name.substr(0, seed));
    } catch (const std::invalid_argument&) {
      return false;
    }
  }
  return true;
}

// Whether `out` holds nothing but what a sweep writes before its sweep.yaml: the lock files
// (SweepFolderLock), the generated worlds and the manifest, all written while the sweep is
// expanded. A sweep refused for a bad sweep file, refused at expansion (a repeated cell, a spawn it
// cannot use) or killed while it generated its worlds leaves such a folder. It was "holds files
// that are not a sweep", so neither the corrected sweep nor the killed one's resume could run
// into it.
bool HoldsOnlyWhatASweepWritesFirst(const fs::path& out) {
  for (const auto& entry : fs::directory_iterator(out)) {
    const std::string name = entry.path().filename().string();
    if (name == "worlds" && entry.is_directory() && !entry.is_symlink()) {
      if (!HoldsOnlyGeneratedSets(entry.path())) return false;
      continue;
    }
    const bool lock = name == "sweep.lock" || (name.rfind("shard-", 0) == 0 && name.size() > 5 &&
                                               name.compare(name.size() - 5, 5, ".lock") == 0);
    bool manifest = false;
    for (const char* file : {"sweep.json", "cells.json", "cells.csv", "sweep.yaml"}) {
      manifest = manifest || IsFileOrItsStagedCopy(name, file);
    }
    if (!(lock || manifest) || !entry.is_regular_file() || entry.is_symlink()) return false;
  }
  return true;
}

}  // namespace

void PrepareSweepFolder(const SweepSpec& spec, const fs::path& out) {
  std::error_code error;
  if (fs::exists(out, error)) {
    if (!fs::is_directory(out)) {
      throw sim::ConfigError(out.string(), "", "exists and is not a folder; choose another --out");
    }
    const fs::path copy = out / "sweep.yaml";
    if (!HoldsOnlyWhatASweepWritesFirst(out) && !fs::is_regular_file(copy)) {
      throw sim::ConfigError(out.string(), "",
                             "holds files that are not a sweep (no sweep.yaml); choose another "
                             "--out");
    }
    if (fs::is_regular_file(copy) && sim::ReadTextFile(copy) != spec.text) {
      throw sim::ConfigError(out.string(), "",
                             "holds results of a different sweep (its sweep.yaml differs): choose "
                             "another --out");
    }
    return;
  }
  if (const auto nowhere = sim::LinkToNowhere(out)) {
    throw sim::ConfigError(out.string(), "",
                           *nowhere + "; make that folder or choose another --out");
  }
  fs::create_directories(out, error);
  if (error) {
    throw sim::ConfigError(out.string(), "", "cannot create the sweep folder: " + error.message());
  }
}

int UsableCores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

bool InShard(const SweepCell& cell, int shard_index, int shard_count) {
  return shard_count <= 1 || cell.index % shard_count == shard_index;
}

namespace {

// cells.csv: one row per cell, as --collect reads it.
std::string CellsCsv(const std::vector<std::string>& axes, const std::vector<SweepCell>& cells) {
  std::vector<std::string> header{"index",  "id",      "experiment", "world",
                                  "family", "profile", "seed"};
  for (const auto& k : axes) header.push_back(k);
  std::string csv = CsvLine(header);
  for (const SweepCell& cell : cells) {
    std::vector<std::string> row{
        std::to_string(cell.index), cell.id, cell.experiment, cell.world, cell.family, cell.profile,
        std::to_string(cell.seed)};
    for (const auto& v : cell.values) row.push_back(v);
    csv += CsvLine(row);
  }
  return csv;
}

// cells.json: every cell with what its run is made from, as a resume reads it back.
std::string CellsJson(const std::vector<SweepCell>& cells) {
  nlohmann::ordered_json full = nlohmann::ordered_json::array();
  for (const SweepCell& cell : cells) {
    full.push_back({{"index", cell.index},
                    {"id", cell.id},
                    {"experiment", cell.experiment},
                    {"world", cell.world},
                    {"family", cell.family},
                    {"profile", cell.profile},
                    {"seed", cell.seed},
                    {"values", cell.values},
                    {"overrides", cell.overrides}});
  }
  return full.dump(1) + "\n";
}

}  // namespace

void WriteSweepManifest(const SweepSpec& spec, const std::vector<SweepCell>& cells,
                        const SweepLayout& layout) {
  fs::create_directories(layout.out);
  const fs::path copy = layout.out / "sweep.yaml";
  if (fs::exists(copy) && sim::ReadTextFile(copy) != spec.text) {
    throw sim::ConfigError(layout.out.string(), "",
                           "holds results of a different sweep (its sweep.yaml differs): choose "
                           "another --out");
  }
  nlohmann::ordered_json meta;
  meta["name"] = spec.name;
  meta["sweep_file"] = spec.source_file;
  std::vector<std::string> experiments;
  for (const auto& e : spec.experiments) experiments.push_back(e.string());
  meta["experiments"] = experiments;
  meta["profiles"] = !spec.profiles.empty();
  std::vector<std::string> keys;
  for (const auto& axis : spec.axes) keys.push_back(axis.key);
  meta["axes"] = keys;
  meta["metrics"] = spec.metrics;
  meta["group_by"] = spec.group_by;
  meta["cells"] = cells.size();
  // cells.json by its hash: sweep.json and cells.json are renamed into place one after the other,
  // so a kill between the two (a resume expanding the sweep again after its experiment was edited)
  // left the new inputs beside the old cells, whose ids and finished runs a later resume then took
  // as the edited experiment's, exit 0 (the s62 fortieth pass).
  const std::string cells_json = CellsJson(cells);
  meta["cells_json_hash"] = StableHash(cells_json);
  std::map<std::string, std::string> inputs = InputHashes(spec);
  for (const SweepCell& cell : cells) {
    for (const auto& [file, hash] : cell.read_files) inputs.try_emplace(file.string(), hash);
    // The world the experiment itself names was not among the inputs: a resume after it was
    // edited kept every finished cell's runs of the old world, the ids of the new one unused (s56).
    if (!cell.world_file.empty() && !inputs.contains(cell.world_file.string())) {
      inputs.emplace(cell.world_file.string(), ReadFileContentHash(cell.world_file));
    }
    // A generated world edited by hand in OUT/worlds was run by the unfinished cells under the
    // generator's label on resume. Recorded relative to OUT, as cells name it, so the folder moves.
    // Hashed once per world, not once per cell that runs it.
    if (!cell.family.empty() && !inputs.contains(cell.world)) {
      inputs.emplace(cell.world, ReadFileContentHash(layout.out / cell.world));
    }
  }
  meta["inputs"] = inputs;
  meta["plywood_build_id"] = sim::ProgramBuildId();
  // The robots' MJCF (models/), part of the program as the build is: a cell's id holds the robot's
  // name, not its file, so a resume after models/p3dx.xml was edited kept the old robot's runs
  // beside new runs of the edited one.
  std::map<std::string, std::string> robots;
  for (const SweepCell& cell : cells) {
    if (!cell.robot.empty() && !robots.contains(cell.robot)) {
      robots.emplace(cell.robot, RobotModelHash(cell.robot));
    }
  }
  meta["robot_models"] = robots;

  sim::WriteTextFile(layout.out / "sweep.json", meta.dump(2) + "\n");
  sim::WriteTextFile(layout.out / "cells.json", cells_json);
  sim::WriteTextFile(layout.out / "cells.csv", CellsCsv(keys, cells));
  if (!fs::exists(copy)) sim::WriteTextFile(copy, spec.text);
}

SweepRunOutcome RunSweepCells(const std::vector<SweepCell>& cells, const SweepLayout& layout,
                              const SweepRunOptions& options) {
  const int jobs = options.jobs > 0 ? options.jobs : UsableCores();
  // Partial runs of an interrupted sweep (of this shard) never count: start them again.
  const fs::path partial_root = layout.PartialRoot();
  for (const fs::path& folder :
       {layout.out / "runs", layout.out / "logs", layout.out / "failures", partial_root}) {
    // A file in a folder's place ended the sweep with "filesystem error: cannot create
    // directories: Not a directory", exit 1 (audit s33).
    std::error_code error;
    if (fs::exists(folder, error) && !fs::is_directory(folder, error)) {
      throw sim::ConfigError(folder.string(), "",
                             "exists and is not a folder (the sweep keeps its " +
                                 folder.filename().string() +
                                 " there): move it away or choose another --out");
    }
    fs::create_directories(folder);
  }

  SweepRunOutcome outcome;
  std::vector<const SweepCell*> todo;
  int done = 0;
  for (const SweepCell& cell : cells) {
    if (!InShard(cell, options.shard_index, options.shard_count)) continue;
    ++outcome.cells;
    for (const auto& entry : fs::directory_iterator(partial_root)) {
      if (entry.path().filename().string().rfind(cell.id + ".", 0) == 0)
        fs::remove_all(entry.path());
    }
    if (sim::WhyNotAFinishedRun(layout.RunDir(cell.id)).empty() &&
        sim::RunBuildId(layout.RunDir(cell.id)) == sim::ProgramBuildId()) {
      ++outcome.already_done;
      ++done;
    } else {
      fs::remove_all(layout.RunDir(cell.id));  // the sweep's own folder: no finished run there
      todo.push_back(&cell);
    }
  }
  Progress progress(outcome.cells, done, options.quiet);
  const Clock::time_point start = Clock::now();
  std::map<pid_t, std::pair<const SweepCell*, fs::path>> running;
  std::size_t next = 0;
  int failed = 0;
  while (next < todo.size() || !running.empty()) {
    while (next < todo.size() && static_cast<int>(running.size()) < jobs) {
      const SweepCell& cell = *todo[next++];
      const fs::path partial = partial_root / (cell.id + "." + std::to_string(cell.index) + "." +
                                               std::to_string(getpid()));
      const pid_t pid =
          StartRun(cell, options.plywood, partial, layout.LogFile(cell.id), layout.out);
      if (pid < 0) {
        // A process limit (`ulimit -u`) reached with runs under way: this cell starts when one
        // of them ends, so the sweep runs as many at once as the limit allows. With none under
        // way it never could: said, with the limit (was "cannot start a run: fork failed").
        const int error = errno;
        if (error == EAGAIN && !running.empty()) {
          --next;
          break;
        }
        throw std::runtime_error("cannot start a run: fork failed: " +
                                 std::string(std::strerror(error)) + sim::ProcessLimitsNote());
      }
      running[pid] = {&cell, partial};
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("sweep: waitpid failed");
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const auto [cell, partial] = it->second;
    running.erase(it);
    ++outcome.ran;
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    const std::string unfinished = code == 0 ? sim::WhyNotAFinishedRun(partial) : "";
    if (code == 0 && unfinished.empty()) {
      fs::rename(partial, layout.RunDir(cell->id));  // the run counts from here on
      fs::remove(layout.FailureFile(cell->id));
      ++done;
    } else {
      std::error_code ignored;
      fs::remove_all(partial, ignored);
      std::string line = ErrorLine(layout.LogFile(cell->id));
      if (code == 0) line = "exited 0 without a finished run: " + unfinished;
      sim::WriteTextFile(layout.FailureFile(cell->id), std::to_string(code) + "\n" + line + "\n");
      ++failed;
    }
    progress.Report(done, failed, false);
  }
  outcome.failed = failed;
  outcome.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  progress.Report(done, failed, true);
  return outcome;
}

std::string WhySweepIsStale(const SweepLayout& layout) {
  const fs::path meta_file = layout.out / "sweep.json";
  if (!fs::is_regular_file(meta_file)) return "";  // nothing expanded yet
  const nlohmann::json meta = nlohmann::json::parse(sim::ReadTextFile(meta_file), nullptr, false);
  if (const auto damage = FindSweepMetaDamage(meta)) {
    return "its sweep.json is damaged (" + (damage->field.empty() ? "" : damage->field + ": ") +
           damage->what + ")";
  }
  const std::string build = meta.value("plywood_build_id", std::string());
  if (build != sim::ProgramBuildId()) {
    return "it was run by another plywood build (build id " +
           (build.empty() ? std::string("unrecorded") : build.substr(0, 12)) + ", this one " +
           sim::ProgramBuildId().substr(0, 12) + ")";
  }
  const auto robots = meta.value("robot_models", std::map<std::string, std::string>{});
  for (const auto& [robot, hash] : robots) {
    const std::string now = RobotModelHash(robot);
    if (now != hash) {
      return "its runs were made with another robot '" + robot + "' (" +
             (now.empty() ? std::string("no such robot now")
                          : sim::FindRobot(robot).mjcf.string() + " changed since") +
             ")";
    }
  }
  return "";
}

namespace {

// What a sweep writes in its folder besides sweep.yaml and its locks (docs/sweeps.md), and the
// staged copies of its files. Starting again removes these and nothing else: a user's notes or
// plots kept in the folder were deleted with the runs (s63).
bool IsSweepsOwnEntry(const std::string& name) {
  for (const char* file :
       {"sweep.json", "cells.json", "cells.csv", "results.csv", "summary.csv", "failures.csv"}) {
    if (IsFileOrItsStagedCopy(name, file)) return true;
  }
  for (const char* folder :
       {"runs", "logs", "failures", "plots", "worlds", "slurm", "bench-jobs1", "bench-jobsN"}) {
    if (name == folder) return true;
  }
  return false;
}

}  // namespace

void StartAgainIfStale(const SweepLayout& layout, bool shard, bool quiet) {
  const std::string why = WhySweepIsStale(layout);
  if (why.empty()) return;
  if (shard) {
    // Other shards may be running in the folder: only a whole sweep may start it again.
    throw sim::ConfigError(layout.out.string(), "",
                           why + "; run the whole sweep once (it starts again) before its shards");
  }
  if (!quiet) {
    std::fprintf(stderr, "plywood sweep: %s: %s; its results no longer hold: starting again\n",
                 layout.out.c_str(), why.c_str());
  }
  // Everything the sweep wrote but the sweep file and the locks is made from them again (worlds
  // included: the generator may have changed too).
  for (const auto& entry : fs::directory_iterator(layout.out)) {
    const std::string name = entry.path().filename().string();
    if (name == "sweep.yaml" || name.ends_with(".lock") || !IsSweepsOwnEntry(name)) continue;
    fs::remove_all(entry.path());
  }
}

std::optional<std::vector<SweepCell>> ReadSweepManifest(const SweepSpec& spec,
                                                        const SweepLayout& layout, bool quiet) {
  const fs::path copy = layout.out / "sweep.yaml";
  const fs::path cells_file = layout.out / "cells.json";
  if (!fs::is_regular_file(copy) || sim::ReadTextFile(copy) != spec.text ||
      !fs::is_regular_file(cells_file))
    return std::nullopt;
  // An edited experiment, profile or world: expand again (a cell's id is the hash of its resolved
  // config and world, so unchanged cells keep their runs and changed ones run anew).
  const nlohmann::json meta =
      nlohmann::json::parse(sim::ReadTextFile(layout.out / "sweep.json"), nullptr, false);
  if (FindSweepMetaDamage(meta)) return std::nullopt;
  const auto recorded = meta.value("inputs", std::map<std::string, std::string>{});
  const auto changed = [&](const std::string& file) {
    if (!quiet) {
      std::fprintf(stderr,
                   "plywood sweep: %s changed since the sweep was expanded: expanding it "
                   "again (cells it changed run anew)\n",
                   file.c_str());
    }
  };
  const std::map<std::string, std::string> inputs = InputHashes(spec);
  for (const auto& [file, hash] : inputs) {
    const auto it = recorded.find(file);
    if (it == recorded.end() || it->second != hash) {
      changed(file);
      return std::nullopt;
    }
  }
  // The files cells read besides their worlds (sonar-net weights, plug-ins, seed 000's later
  // rooms), recorded as they were: a sweep resumed after the weights were retrained in place kept
  // the old network's runs.
  for (const auto& [file, hash] : recorded) {
    if (inputs.count(file)) continue;
    const fs::path path = fs::path(file).is_relative() ? layout.out / file : fs::path(file);
    if (!perception::IsRegularFile(path) || ReadFileContentHash(path) != hash) {
      changed(path.string());
      return std::nullopt;
    }
  }
  // cells.json of another expansion than sweep.json's (a kill between their writes): expand again.
  const std::string cells_json = sim::ReadTextFile(cells_file);
  if (meta.value("cells_json_hash", std::string()) != StableHash(cells_json)) return std::nullopt;
  std::vector<SweepCell> cells;
  try {
    for (const auto& item : nlohmann::json::parse(cells_json)) {
      SweepCell cell;
      cell.index = item.at("index").get<int>();
      cell.id = item.at("id").get<std::string>();
      cell.experiment = item.at("experiment").get<std::string>();
      cell.profile = item.at("profile").get<std::string>();
      cell.world = item.at("world").get<std::string>();
      cell.family = item.at("family").get<std::string>();
      cell.seed = item.at("seed").get<std::uint64_t>();
      cell.values = item.at("values").get<std::vector<std::string>>();
      cell.overrides = item.at("overrides").get<std::vector<std::string>>();
      cells.push_back(cell);
    }
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;  // damaged: expand the sweep again
  }
  // A cells.json cut or edited into other valid JSON (`[]`, cells left out) would otherwise be
  // taken as the whole sweep: the cells it lost would never run, and a resume would report them
  // "not run" for ever. An id that is not the 16 hex digits of a run folder's name would be
  // removed and written outside runs/.
  const auto axes = meta.value("axes", std::vector<std::string>{});
  if (cells.size() != meta.value("cells", std::size_t{0})) return std::nullopt;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const SweepCell& cell = cells[i];
    if (cell.index != static_cast<int>(i) || cell.values.size() != axes.size() ||
        cell.id.size() != 16 ||
        cell.id.find_first_not_of("0123456789abcdef") != std::string::npos) {
      return std::nullopt;
    }
  }
  // cells.csv is what --collect reads: one cut at a line's end (or edited) lost its cells from
  // results.csv and summary.csv while the resume said "2 of 2 runs finished". Expanding again
  // rewrites it.
  const fs::path cells_csv = layout.out / "cells.csv";
  if (!fs::is_regular_file(cells_csv) || sim::ReadTextFile(cells_csv) != CellsCsv(axes, cells)) {
    return std::nullopt;
  }
  return cells;
}

}  // namespace plywood::eval
