#include "eval/score/score_report.h"

#include <algorithm>
#include <stdexcept>
#include <system_error>

#include "sim/config/config_error.h"
#include "sim/runner/text_file.h"

namespace plywood::eval {
void CheckScoreOut(const std::filesystem::path& out, const std::filesystem::path& run_dir,
                   const std::filesystem::path& scored) {
  namespace fs = std::filesystem;
  // "s.json/" printed the whole table of figures, then was refused as a folder (s57's left item).
  const std::string last = out.filename().string();
  if (last.empty() || last == "." || last == "..") {
    throw sim::ConfigError(out.string(), "--out",
                           "names a folder (it ends in '/', '.' or '..'); give a file name "
                           "(scores.json)");
  }
  // A pipe or a device (/dev/stdout into `| jq`: "pipe:[N]", no path) is written to as it is; it
  // was refused "cannot be resolved: No such file or directory" (s63 fiftieth pass).
  if (sim::IsADeviceOrAPipe(out)) return;  // never the run's folder nor the scored file
  // The error_code form: a symbolic-link loop as --out threw filesystem_error, a line naming no
  // flag and exit 1.
  std::error_code error;
  const fs::path target = fs::weakly_canonical(fs::absolute(out), error);
  if (error)
    throw sim::ConfigError(out.string(), "--out", "cannot be resolved: " + error.message());
  const fs::path run = fs::weakly_canonical(fs::absolute(run_dir));
  const auto [run_end, target_it] =
      std::mismatch(run.begin(), run.end(), target.begin(), target.end());
  if (run_end == run.end()) {
    throw sim::ConfigError(
        out.string(), "--out",
        "is inside the scored run's folder " + run_dir.string() + "; write the scores elsewhere");
  }
  if (target == fs::weakly_canonical(fs::absolute(scored))) {
    throw sim::ConfigError(out.string(), "--out", "is the file being scored");
  }
  if (fs::is_directory(target)) {
    throw sim::ConfigError(out.string(), "--out", "is a folder; give a file name (scores.json)");
  }
  // A folder that is not there (or a file where it should be) printed the whole table of figures
  // and then "cannot write: No such file or directory", exit 2 (s63).
  const fs::path folder = target.parent_path();
  if (!fs::is_directory(folder, error)) {
    throw sim::ConfigError(
        out.string(), "--out",
        "cannot write: " + folder.string() +
            (fs::exists(folder, error) ? " is not a folder" : " does not exist; make it first"));
  }
}

void WriteScoreJson(const ScoreReport& report, const std::filesystem::path& out,
                    const std::filesystem::path& run_dir, const std::filesystem::path& scored) {
  CheckScoreOut(out, run_dir, scored);
  const std::filesystem::path target =
      sim::IsADeviceOrAPipe(out)
          ? out
          : std::filesystem::weakly_canonical(std::filesystem::absolute(out));
  // Staged beside the target and renamed into place (WriteTextFile): written in place, a full
  // disk or a file-size limit left an earlier scores file cut to 0 bytes.
  try {
    sim::WriteTextFile(target, report.metrics.ToJson());
  } catch (const std::runtime_error& e) {  // "TARGET: write failed: No space left on device"
    std::string what = e.what();
    const std::string prefix = target.string() + ": ";
    if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
    throw sim::ConfigError(out.string(), "--out", what);
  }
}

}  // namespace plywood::eval
