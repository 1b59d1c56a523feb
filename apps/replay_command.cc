// plywood replay LOG [--extractor NAME] [--set EXTRACTOR.KEY=VALUE]... [--skip-bad] [--out DIR]
//                    [--force]

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "apps/command.h"
#include "eval/lines/log_replay_run.h"
#include "eval/printed_figure.h"
#include "perception/lines/line_extractor_factory.h"

namespace plywood::apps {
namespace {

std::string ExtractorList() {
  std::string names;
  for (const std::string& name : perception::LineExtractorNames()) {
    names += (names.empty() ? "" : ", ") + name;
  }
  return names;
}

void PrintSummary(const eval::LogReplayRequest& request, const eval::LogReplaySummary& summary) {
  const perception::ReplayResult& r = summary.result;
  std::printf("%-22s %s (%ld scans, %ld lines skipped)\n", "log", request.log.c_str(), r.scans,
              static_cast<long>(summary.skipped_lines));
  std::printf("%-22s %s\n", "extractor", request.extractor.c_str());
  std::printf("%-22s %.4f of %ld valid rays (lines only)\n", "rays explained", r.rays.Fraction(),
              r.rays.rays);
  std::printf("%-22s %.4f (lines + %ld circles)\n", "", r.rays_with_circles.Fraction(), r.circles);
  // Undefined (metrics.json's null) with no ray explained, no line found: said, not "nan".
  const double rms_m = r.rays.RmsM();
  std::printf("%-22s %s\n", "rms distance",
              std::isfinite(rms_m) ? (eval::PrintedFigure(rms_m, "%.4f") + " m").c_str()
                                   : "null (no ray explained)");
  std::printf("%-22s %s\n", "rays per line",
              std::isfinite(r.RaysPerLine()) ? eval::PrintedFigure(r.RaysPerLine(), "%.1f").c_str()
                                             : "null (no line found)");
  std::printf("%-22s %.2f\n", "lines per scan", r.LinesPerScan());
  std::printf("%-22s %.1f us (%.0f scans/s)\n", "time per scan", r.UsPerScan(),
              r.UsPerScan() > 0 ? 1e6 / r.UsPerScan() : 0.0);
  std::printf("%-22s %s\n", "results", summary.out_dir.c_str());
}

}  // namespace

Command AddReplayCommand(CLI::App& app) {
  auto request = std::make_shared<eval::LogReplayRequest>();
  CLI::App* cli = app.add_subcommand(
      "replay",
      "Run a line extractor on every scan of a CARMEN log (plain or .gz) and score how much of the "
      "data its lines explain");
  cli->add_option("LOG", request->log, "CARMEN log file")->required();
  cli->add_option("--extractor", request->extractor, "line extractor: " + ExtractorList())
      ->type_name("NAME")
      ->capture_default_str();
  cli->add_option("--set", request->overrides,
                  "extractor option as in an experiment's lines: section, e.g. "
                  "split_and_merge.min_points=5 (repeatable)")
      ->type_name("EXTRACTOR.KEY=VALUE")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cli->add_flag("--skip-bad", request->skip_bad,
                "skip and count malformed log lines instead of stopping at the first");
  cli->add_option("--out", request->out_dir, "results directory (docs/lines.md)")
      ->type_name("DIR")
      ->default_str("runs/replay-LOGFILE-EXTRACTOR");
  cli->add_flag("--force", request->force,
                "replace an earlier run in --out (a directory with its config.yaml and "
                "metrics.json); refused if it holds any file a run does not write");
  cli->footer(
      "Example:\n"
      "  plywood replay ../shared/data/carmen/intel-corrected.log.gz --extractor split_and_merge "
      "--set split_and_merge.min_points=5 --out runs/intel");
  return {cli, [request] {
            PrintSummary(*request, eval::RunLogReplay(*request));
            return 0;
          }};
}

}  // namespace plywood::apps
