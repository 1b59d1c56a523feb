// plywood score trajectory|lines|grid RUN_DIR FILE [--out FILE.json] [--name NAME]
//               [--resolution M --origin X,Y [--threshold P]]

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "apps/command.h"
#include "eval/score/grid_score.h"
#include "eval/score/lines_score.h"
#include "eval/score/score_report.h"
#include "eval/score/trajectory_score.h"
#include "perception/logs/parse_number.h"

namespace plywood::apps {
namespace {

// "X,Y" as two finite numbers. @throws UsageError.
Eigen::Vector2d ParseOrigin(const std::string& text) {
  const auto comma = text.find(',');
  const auto x = perception::ParseFiniteNumber(text.substr(0, comma));
  const auto y = comma == std::string::npos ? std::nullopt
                                            : perception::ParseFiniteNumber(text.substr(comma + 1));
  if (!x || !y) throw UsageError("score: --origin: expected X,Y in metres, got '" + text + "'");
  return {*x, *y};
}

}  // namespace

Command AddScoreCommand(CLI::App& app) {
  struct Flags {
    std::string what;
    std::string run_dir;
    std::string file;
    std::string out;
    std::string name;
    double resolution_m = 0.0;
    std::string origin;
    double threshold = 0.5;
  };
  auto flags = std::make_shared<Flags>();
  CLI::App* cli = app.add_subcommand(
      "score",
      "Score a trajectory (TUM or CSV), per-scan line segments (CSV) or an occupancy grid (PNG, "
      "PGM) computed by any program against a finished run's ground truth, with the runner's own "
      "scorers");
  cli->add_option("KIND", flags->what, "trajectory, lines or grid")
      ->required()
      ->check(CLI::IsMember({"trajectory", "lines", "grid"}));
  cli->add_option("RUN_DIR", flags->run_dir, "a finished `plywood run` directory")->required();
  cli->add_option("FILE", flags->file, "the file to score (docs/run_outputs.md)")->required();
  cli->add_option("--out", flags->out, "also write the figures as JSON (metrics.json's keys)")
      ->type_name("FILE.json");
  CLI::Option* name =
      cli->add_option("--name", flags->name,
                      "trajectory/lines: the name the figures get (default: from the file)")
          ->type_name("NAME");
  CLI::Option* resolution =
      cli->add_option("--resolution", flags->resolution_m, "grid: metres per pixel (required)")
          ->type_name("M");
  CLI::Option* origin = cli->add_option("--origin", flags->origin,
                                        "grid: world position of the lower-left pixel's corner "
                                        "(required)")
                            ->type_name("X,Y");
  CLI::Option* threshold = cli->add_option("--threshold", flags->threshold,
                                           "grid: occupancy above which a pixel counts as not free")
                               ->type_name("P")
                               ->capture_default_str();
  cli->footer(
      "Examples:\n"
      "  plywood score trajectory runs/default-seed1 my_estimate.tum\n"
      "  plywood score lines runs/default-seed1 my_lines.csv --out scores.json\n"
      "  plywood score grid runs/seed001_room_1-seed1 map.pgm --resolution 0.05 --origin "
      "-2,-2");
  return {cli, [flags, name, resolution, origin, threshold] {
            const bool grid = flags->what == "grid";
            for (const CLI::Option* o : {resolution, origin, threshold}) {
              if (!grid && o->count() > 0) {
                throw UsageError("score: " + o->get_name() + " is for score grid only");
              }
            }
            if (grid && name->count() > 0) {
              throw UsageError("score: --name is for score trajectory and lines");
            }
            // `--name ''` fell back to the file's name without a word (s56's left item).
            if (name->count() > 0 && flags->name.empty()) {
              throw UsageError(
                  "score: --name: empty; give the name the figures get, or leave --name out");
            }
            // Before scoring: a refused --out printed the whole table first (s57's left item).
            if (!flags->out.empty()) eval::CheckScoreOut(flags->out, flags->run_dir, flags->file);
            eval::ScoreReport report;
            if (flags->what == "trajectory") {
              report =
                  eval::ScoreTrajectoryFile(flags->run_dir, flags->file, {.name = flags->name});
            } else if (flags->what == "lines") {
              report = eval::ScoreLinesFile(flags->run_dir, flags->file, {.name = flags->name});
            } else {
              if (resolution->count() == 0 || origin->count() == 0) {
                throw UsageError(
                    "score: grid needs --resolution M (metres per pixel) and --origin X,Y");
              }
              eval::GridPlacement placement;
              placement.resolution_m = flags->resolution_m;
              placement.origin_W = ParseOrigin(flags->origin);
              placement.occupied_threshold = flags->threshold;
              placement.Validate();
              report = eval::ScoreGridFile(flags->run_dir, flags->file, placement);
            }
            std::fputs(report.table.c_str(), stdout);
            if (!flags->out.empty()) {
              eval::WriteScoreJson(report, flags->out, flags->run_dir, flags->file);
              std::printf("%-18s %s\n", "results", flags->out.c_str());
            }
            return 0;
          }};
}

}  // namespace plywood::apps
