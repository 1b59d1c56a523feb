#include "apps/score_command.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "apps/command_line.h"
#include "eval/score/grid_score.h"
#include "eval/score/lines_score.h"
#include "eval/score/trajectory_score.h"
#include "perception/logs/parse_number.h"

namespace plywood::apps {
namespace {

constexpr const char* kUsage =
    "usage: plywood score trajectory|lines|grid RUN_DIR FILE [--out FILE.json] [--name NAME] "
    "[--resolution M --origin X,Y [--threshold P]] (see plywood --help)";

// "X,Y" as two finite numbers. @throws UsageError.
Eigen::Vector2d ParseOrigin(const std::string& text) {
  const auto comma = text.find(',');
  const auto x = perception::ParseFiniteNumber(text.substr(0, comma));
  const auto y = comma == std::string::npos ? std::nullopt
                                            : perception::ParseFiniteNumber(text.substr(comma + 1));
  if (!x || !y) throw UsageError{"--origin: expected X,Y in metres, got '" + text + "'"};
  return {*x, *y};
}

}  // namespace

int ScoreCommand(const std::vector<std::string>& args) {
  const CommandLine line(args, {"--out", "--name", "--resolution", "--origin", "--threshold"}, {});
  const std::vector<std::string>& positional = line.positional();
  if (positional.size() != 3) throw UsageError{kUsage};
  const std::string& what = positional[0];
  const std::filesystem::path run_dir = positional[1], file = positional[2];
  const std::string name = line.Value("--name").value_or("");
  const bool grid = what == "grid";
  for (const char* flag : {"--resolution", "--origin", "--threshold"}) {
    if (!grid && line.Value(flag)) throw UsageError{std::string(flag) + " is for score grid only"};
  }
  if (grid && line.Value("--name")) throw UsageError{"--name is for score trajectory and lines"};

  eval::ScoreReport report;
  if (what == "trajectory") {
    report = eval::ScoreTrajectoryFile(run_dir, file, {.name = name});
  } else if (what == "lines") {
    report = eval::ScoreLinesFile(run_dir, file, {.name = name});
  } else if (grid) {
    if (!line.Value("--resolution") || !line.Value("--origin")) {
      throw UsageError{"score grid needs --resolution M (metres per pixel) and --origin X,Y"};
    }
    eval::GridPlacement placement;
    placement.resolution_m = *line.Number("--resolution");
    placement.origin_W = ParseOrigin(*line.Value("--origin"));
    placement.occupied_threshold = line.Number("--threshold").value_or(0.5);
    placement.Validate();
    report = eval::ScoreGridFile(run_dir, file, placement);
  } else {
    throw UsageError{"score: unknown kind '" + what + "' (trajectory, lines or grid)"};
  }
  std::fputs(report.table.c_str(), stdout);
  if (const auto out = line.Value("--out")) {
    std::ofstream json(*out, std::ios::binary);
    json << report.metrics.ToJson();
    json.flush();
    if (!json) throw std::runtime_error(*out + ": cannot write");
    std::printf("%-18s %s\n", "results", out->c_str());
  }
  return 0;
}

}  // namespace plywood::apps
