#include "sim/runner/run_directory.h"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string_view>

#include "sim/config/config_error.h"
#include "sim/runner/build_id.h"
#include "sim/runner/json_text.h"
#include "sim/runner/link_to_nowhere.h"
#include "sim/runner/text_file.h"

namespace plywood::sim {
namespace {

namespace fs = std::filesystem;

constexpr const char* kStagingInfix = ".partial-";

// Every file name a run or a protocol writes (docs/run_outputs.md). --force removes these and
// nothing else.
bool IsFixedRunOutputName(const std::string& name) {
  static constexpr std::string_view kNames[] = {"config.yaml",
                                                "metrics.json",
                                                "timing.json",
                                                "cognitive_map.json",
                                                "trajectory.csv",
                                                "walls.csv",
                                                "laser.log",
                                                "laser_hits.csv",
                                                "laser_scans.csv",
                                                "lines.csv",
                                                "circles.csv",
                                                "spot_round_objects.csv",
                                                "sonar.csv",
                                                "ir_ring.csv",
                                                "ir_scanner.csv",
                                                "encoders.csv",
                                                "gyro.csv",
                                                "bumpers.csv",
                                                "rooms.csv",
                                                "umbmark_runs.csv",
                                                "snapshot.png",
                                                "occupancy_grid.png",
                                                "occupancy_partitions.png",
                                                "segments.png",
                                                "lines_truth.csv",
                                                "lines_odometry.csv",
                                                "geometric_map.json",
                                                "geometric_map.png",
                                                "scans.csv",
                                                "exploration_log.csv",
                                                kRunCompleteFile};
  for (std::string_view known : kNames) {
    if (name == known) return true;
  }
  return name.starts_with("trajectory.") && name.ends_with(".tum");
}

// The files a finished run lists in its complete.json (paths relative to its folder), or nothing
// when it has no record (a run older than the record, a killed run's staging folder). A record
// that is there but unreadable (corrupt, or a folder of that name) lists nothing: it was read as
// no record, so a user's picture passed by its name and --force deleted it (s63).
bool HasRecord(const fs::path& dir) {
  std::error_code error;
  return fs::exists(fs::symlink_status(dir / kRunCompleteFile, error));
}

// The record's JSON when it is a completion record ({"files": {...}}), else null.
nlohmann::json ReadableRecord(const fs::path& dir) {
  std::error_code error;
  if (!fs::is_regular_file(dir / kRunCompleteFile, error)) return nullptr;
  nlohmann::json record =
      nlohmann::json::parse(ReadTextFile(dir / kRunCompleteFile), nullptr, false);
  if (!record.is_object() || !record.contains("files") || !record["files"].is_object()) {
    return nullptr;
  }
  return record;
}

std::optional<std::set<std::string>> ListedRunFiles(const fs::path& dir) {
  if (!HasRecord(dir)) return std::nullopt;
  const nlohmann::json record = ReadableRecord(dir);
  if (record.is_null()) return std::set<std::string>();
  std::set<std::string> listed;
  for (const auto& [name, size] : record["files"].items()) listed.insert(name);
  return listed;
}

// The first entry under `folder`, inside the run folder `root`, that no run writes. A fixed name
// (a run of an older version may have left one its successor does not write) is the run's; a
// picture named after a room or a cloud (<room>.png) only when the run's record lists it, or by
// its name when there is no record. A subfolder is the run's when everything in it is and it is no
// finished run of its own: a protocol's runs (UMBmark's before/cw_1) have no complete.json.
fs::path FirstForeignEntryBelow(const fs::path& root, const fs::path& folder,
                                const std::optional<std::set<std::string>>& listed) {
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    if (entry.is_symlink()) return entry.path();
    // A run writes its fixed names as files: a folder so named (complete.json/) is not its own.
    if (entry.is_directory() && IsFixedRunOutputName(entry.path().filename().string())) {
      return entry.path();
    }
    if (entry.is_directory()) {
      if (fs::exists(entry.path() / kRunCompleteFile)) return entry.path();
      const fs::path inner = FirstForeignEntryBelow(root, entry.path(), listed);
      if (!inner.empty()) return inner;
      continue;
    }
    if (!entry.is_regular_file()) return entry.path();
    const std::string name = entry.path().filename().string();
    if (IsFixedRunOutputName(name)) continue;
    const bool written =
        listed ? listed->contains(entry.path().lexically_relative(root).generic_string())
               : name.ends_with(".png");
    if (!written) return entry.path();
  }
  return {};
}

// The first entry under `dir` that no run writes, or empty when there is none. By names alone, a
// user's own picture (any *.png) and another run put in a subfolder (`--out /tmp/o/S` beside
// `--out /tmp/o`) passed as the run's, and --force deleted them (s63).
fs::path FirstForeignEntry(const fs::path& dir) {
  return FirstForeignEntryBelow(dir, dir, ListedRunFiles(dir));
}

// `path` absolute and without a trailing '/' ("runs/x/" and "runs/x" are one target).
// A symbolic link is followed to the folder it names: the staging folder goes beside that folder
// (on its file system), and the finished run is renamed onto it, not onto the link (which failed
// with "Not a directory" after the whole run).
fs::path Normalised(const fs::path& path) {
  fs::path p = fs::absolute(path).lexically_normal();
  if (!p.has_filename() && p.has_parent_path()) p = p.parent_path();
  std::error_code error;
  if (fs::is_symlink(p, error)) {
    const fs::path resolved = fs::canonical(p, error);
    if (!error) p = resolved;
  }
  return p;
}

// The staging folders of runs into `target` (TARGET.partial-PID), with the PID of each.
std::map<fs::path, long> StagingFolders(const fs::path& target) {
  std::map<fs::path, long> found;
  const std::string prefix = target.filename().string() + kStagingInfix;
  std::error_code error;
  for (fs::directory_iterator it(target.parent_path(), error), end; !error && it != end;
       it.increment(error)) {
    const std::string name = it->path().filename().string();
    // A run makes its staging folder itself: a link of that name is the user's (it was deleted).
    if (!name.starts_with(prefix) || it->is_symlink() || !it->is_directory()) continue;
    const std::string pid = name.substr(prefix.size());
    if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) continue;
    found[it->path()] = std::stol(pid);
  }
  return found;
}

bool ProcessIsGone(long pid) { return kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH; }

// complete.json: every file under `dir` but timing.json, by path relative to `dir`, with its size.
std::string CompletionRecord(const fs::path& dir) {
  nlohmann::json files = nlohmann::json::object();  // sorted by path: the same bytes every time
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    const std::string name = entry.path().lexically_relative(dir).generic_string();
    if (name == "timing.json" || name == kRunCompleteFile) continue;
    files[name] = entry.file_size();
  }
  nlohmann::json record{{"files", files}};
  // Which code made the run, so a sweep never mixes runs of different builds.
  if (!ProgramBuildId().empty()) record["plywood_build_id"] = ProgramBuildId();
  return WriteJson(record);
}

}  // namespace

bool HoldsPlywoodRun(const fs::path& dir) {
  std::ifstream config(dir / "config.yaml");
  std::string first_line;
  return config && std::getline(config, first_line) && first_line.starts_with("name: ") &&
         fs::is_regular_file(dir / "metrics.json");
}

std::string WhyNotAFinishedRun(const fs::path& dir) {
  // Where runs into `dir` that did not finish left their output (looked up only when needed: a
  // sweep checks thousands of finished runs in one folder).
  const auto interrupted = [&dir] {
    std::string where;
    for (const auto& [folder, pid] : StagingFolders(Normalised(dir))) {
      where = "; " + folder.filename().string() + " beside it is the partial output of a run " +
              (ProcessIsGone(pid) ? "that was killed" : "still running");
    }
    return where;
  };
  std::error_code error;
  if (!fs::is_directory(dir, error)) {
    return (fs::exists(dir, error) ? "not a directory" : "no such directory") + interrupted();
  }
  const fs::path marker = dir / kRunCompleteFile;
  if (!fs::is_regular_file(marker, error)) {
    return std::string("no ") + kRunCompleteFile +
           " (the run that wrote it did not finish: killed, failed or still running)" +
           interrupted();
  }
  const nlohmann::json record = nlohmann::json::parse(ReadTextFile(marker), nullptr, false);
  if (!record.is_object() || !record.contains("files") || !record["files"].is_object()) {
    return std::string(kRunCompleteFile) + " is not a completion record";
  }
  for (const auto& [name, size] : record["files"].items()) {
    const fs::path file = dir / name;
    if (!fs::is_regular_file(file, error)) return name + " is missing (listed in complete.json)";
    if (!size.is_number_unsigned() || fs::file_size(file, error) != size.get<std::uintmax_t>()) {
      return name + " is " + std::to_string(fs::file_size(file, error)) +
             " bytes, complete.json says " + size.dump() + " (truncated or changed after the run)";
    }
  }
  return "";
}

void RequireFinishedRun(const fs::path& dir) {
  const std::string why = WhyNotAFinishedRun(dir);
  if (!why.empty()) throw ConfigError(dir.string(), "", "not a finished run: " + why);
}

std::string WhyNotAFinishedRunOrPart(const fs::path& dir) {
  const std::string why = WhyNotAFinishedRun(dir);
  std::error_code error;
  if (why.empty() || !fs::is_directory(dir, error) || fs::exists(dir / kRunCompleteFile, error)) {
    return why;
  }
  // A multi-run protocol's runs (UMBmark's before/cw_1) have no complete.json of their own: the
  // protocol's folder, at most two levels up, lists their files with its own. They were refused
  // as "no complete.json", though the docs name them as scorable one by one (s49).
  fs::path part;
  fs::path folder = Normalised(dir);
  for (int level = 0; level < 2 && folder.has_parent_path() && folder != folder.root_path();
       ++level) {
    part = part.empty() ? folder.filename() : folder.filename() / part;
    folder = folder.parent_path();
    if (!fs::is_regular_file(folder / kRunCompleteFile, error)) continue;
    if (const std::string protocol_why = WhyNotAFinishedRun(folder); !protocol_why.empty()) {
      return why + "; " + folder.string() +
             ", which lists it, is not finished either: " + protocol_why;
    }
    // The record was read and every file it lists checked above.
    const nlohmann::json record =
        nlohmann::json::parse(ReadTextFile(folder / kRunCompleteFile), nullptr, false);
    if (record["files"].contains((part / "config.yaml").generic_string())) return "";
    return why;
  }
  return why;
}

void RequireFinishedRunOrPart(const fs::path& dir) {
  const std::string why = WhyNotAFinishedRunOrPart(dir);
  if (!why.empty()) throw ConfigError(dir.string(), "", "not a finished run: " + why);
}

StagedRunDirectory::StagedRunDirectory(const fs::path& target, bool force)
    : given_(target), target_(Normalised(target)) {
  std::error_code error;
  const fs::file_status status = fs::status(target_, error);
  if (const auto nowhere = LinkToNowhere(target_)) {
    throw ConfigError(given_.string(), "", *nowhere + "; make that folder or choose another --out");
  }
  if (!fs::exists(status)) {
    // Made now, so an unwritable place is refused before anything is simulated.
    fs::create_directories(target_, error);
    if (error) {
      throw ConfigError(given_.string(), "", "cannot create the output folder: " + error.message());
    }
    created_target_ = true;
  } else if (!fs::is_directory(status)) {
    throw ConfigError(given_.string(), "", "exists and is not a directory; choose another --out");
  } else if (!fs::is_empty(target_)) {
    if (!HoldsPlywoodRun(target_)) {
      throw ConfigError(given_.string(), "",
                        "holds files that are not a Plywood run (no config.yaml and "
                        "metrics.json); choose another --out (--force never deletes them)");
    }
    if (!force) {
      throw ConfigError(given_.string(), "",
                        "already holds an earlier run; add --force to replace it, or choose "
                        "another --out");
    }
    const fs::path foreign = FirstForeignEntry(target_);
    if (!foreign.empty()) {
      const std::string what = foreign.lexically_relative(target_).string();
      const bool unreadable = HasRecord(target_) && ReadableRecord(target_).is_null();
      const std::string why =
          !unreadable ? "holds an earlier run and also " + what + ", which no run writes"
          : what == kRunCompleteFile
              ? "holds an earlier run whose " + what + " is a folder, not a completion record"
              : "holds an earlier run whose " + std::string(kRunCompleteFile) +
                    " is not a completion record, and also " + what +
                    ", which only that record could show to be the run's";
      throw ConfigError(given_.string(), "",
                        why +
                            "; --force deletes only a run's own files: move it away or choose "
                            "another --out");
    }
    replace_ = true;
  }
  // What killed runs into this target left behind (their own files only).
  for (const auto& [folder, pid] : StagingFolders(target_)) {
    if (ProcessIsGone(pid) && FirstForeignEntry(folder).empty()) fs::remove_all(folder, error);
  }
  staging_ = target_;
  staging_ += kStagingInfix + std::to_string(getpid());
  fs::remove_all(staging_, error);
  if (!fs::create_directory(staging_, error) || error) {
    const std::string why = error ? error.message() : "it exists";
    if (created_target_) fs::remove(target_, error);
    throw ConfigError(given_.string(), "",
                      "cannot make the staging folder " + staging_.filename().string() +
                          " beside it (a run is written there and renamed into place): " + why);
  }
}

StagedRunDirectory::~StagedRunDirectory() {
  if (committed_) return;
  std::error_code error;
  fs::remove_all(staging_, error);
  if (created_target_ && fs::is_empty(target_, error)) fs::remove(target_, error);
}

void WriteCompletionRecord(const fs::path& dir) {
  WriteTextFile(dir / kRunCompleteFile, CompletionRecord(dir));
}

void StagedRunDirectory::Commit() {
  WriteCompletionRecord(staging_);
  std::error_code error;
  if (replace_ && fs::is_empty(target_, error)) replace_ = false;  // emptied meanwhile
  if (replace_) {
    // The earlier run is moved aside, the new one renamed in, then the earlier one deleted: at
    // no moment does the target hold a mixture of the two.
    if (!HoldsPlywoodRun(target_) || !FirstForeignEntry(target_).empty()) {
      committed_ = true;
      throw ConfigError(given_.string(), "",
                        "changed while the run was going (it now holds files no run writes); the "
                        "results are in " +
                            staging_.string());
    }
    fs::path old = target_;
    old += ".replaced-" + std::to_string(getpid());
    fs::rename(target_, old, error);
    if (!error) fs::rename(staging_, target_, error);
    if (error) {
      committed_ = true;
      throw ConfigError(given_.string(), "",
                        "cannot replace the earlier run: " + error.message() +
                            "; the new results are in " + staging_.string());
    }
    fs::remove_all(old, error);
  } else {
    fs::rename(staging_, target_, error);  // onto the empty target
    if (error) {
      committed_ = true;
      throw ConfigError(given_.string(), "",
                        "cannot move the finished run into place (" + error.message() +
                            ": did another run finish there meanwhile?); the results are in " +
                            staging_.string());
    }
  }
  committed_ = true;
}

}  // namespace plywood::sim
