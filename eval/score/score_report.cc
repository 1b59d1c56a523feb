#include "eval/score/score_report.h"

#include <algorithm>
#include <fstream>

#include "sim/config/config_error.h"

namespace plywood::eval {

void WriteScoreJson(const ScoreReport& report, const std::filesystem::path& out,
                    const std::filesystem::path& run_dir, const std::filesystem::path& scored) {
  namespace fs = std::filesystem;
  const fs::path target = fs::weakly_canonical(fs::absolute(out));
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
  std::ofstream json(target, std::ios::binary);
  json << report.metrics.ToJson();
  json.flush();
  if (!json) throw sim::ConfigError(out.string(), "--out", "cannot write the file");
}

}  // namespace plywood::eval
