#include "eval/score/lines_score.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "eval/lines/line_scan_scorer.h"
#include "eval/lines/lines_csv.h"
#include "eval/printed_figure.h"
#include "eval/score/run_laser_scans.h"
#include "eval/score/trajectory_file.h"
#include "msgs/shortest_number.h"
#include "perception/lines/line_segment.h"
#include "sim/config/config_error.h"

namespace plywood::eval {
namespace {

// A file written in another frame (the world's, as mapping programs write segments) scored
// recall 0.02 against walls it had found, exit 0: its ends lie far from every return.
constexpr double kMaxEndToReturnM = perception::kMaxEndToScanPointM;

void RequireNearItsScansReturns(const LinesCsvRow& row, const TruthScan& scan,
                                const std::filesystem::path& file) {
  const std::string where = file.string() + ":" + std::to_string(row.line_number);
  const std::string scan_name = "scan " + std::to_string(row.scan);
  if (scan.points.empty()) {
    throw sim::ConfigError(where, "scan",
                           scan_name + " has no return within range_cut_m to fit a segment to");
  }
  const perception::LineSegment& s = row.segment;
  for (const auto& [end, field] : {std::pair{s.start, "x1_m, y1_m"}, {s.end, "x2_m, y2_m"}}) {
    // hypot, not norm: an end at 1e300 is 1e300 m away, where the squared norm overflowed and
    // the message read "lies null m" (s54).
    double nearest = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector2d& p : scan.points.points)
      nearest = std::min(nearest, std::hypot(p.x() - end.x(), p.y() - end.y()));
    if (nearest <= kMaxEndToReturnM) continue;
    throw sim::ConfigError(
        where, field,
        "the end (" + sim::FormatNumber(end.x()) + ", " + sim::FormatNumber(end.y()) + ") lies " +
            msgs::ShortestNumber(nearest) + " m from every return of " + scan_name +
            ", more than " + sim::FormatNumber(kMaxEndToReturnM) +
            " m: segments are in their scan's sensor frame (laser_scans.csv), not the world's");
  }
}

// A row repeated whole (a file written twice, or appended to itself) counted each segment twice:
// lines_per_scan doubled and points_per_line halved, exit 0. An extractor reports a segment once.
// The ends are compared as a pair in either order: a segment written again from its other end
// (a tool that walks its lines both ways) is the same segment, and counted twice just the same.
void RequireNoRepeatedRow(const std::vector<LinesCsvRow>& rows, const std::filesystem::path& file) {
  using End = std::pair<double, double>;
  std::map<std::tuple<long, std::string, End, End>, std::size_t> first_line;
  for (const LinesCsvRow& row : rows) {
    const perception::LineSegment& s = row.segment;
    const End a{s.start.x(), s.start.y()};
    const End b{s.end.x(), s.end.y()};
    const auto [at, inserted] = first_line.emplace(
        std::tuple{row.scan, row.extractor, std::min(a, b), std::max(a, b)}, row.line_number);
    if (inserted) continue;
    throw sim::ConfigError(file.string() + ":" + std::to_string(row.line_number), "x1_m",
                           "repeats line " + std::to_string(at->second) + " (scan " +
                               std::to_string(row.scan) + ", extractor " + row.extractor +
                               ", the same ends, in either order): an extractor reports each "
                               "segment once; was the file written twice?");
  }
}

}  // namespace

ScoreReport ScoreLinesFile(const std::filesystem::path& run_dir, const std::filesystem::path& file,
                           const LinesScoreOptions& options) {
  const RunLaserScans run = LoadRunLaserScans(run_dir);
  const std::string name = options.name.empty() ? TrajectoryNameOf(file) : options.name;
  if (!IsMetricName(name)) {
    throw sim::ConfigError("--name", "", NotAMetricName(name));
  }
  const std::vector<LinesCsvRow> rows = ReadLinesCsv(file, name, !options.name.empty());

  // Segments by extractor (in order of first appearance), then by scan, in file order.
  std::vector<ExtractorScore> scores;
  std::vector<std::vector<std::vector<perception::LineSegment>>> found;
  const long scans = static_cast<long>(run.scans.size());
  for (const LinesCsvRow& row : rows) {
    if (row.scan >= scans) {
      throw sim::ConfigError(file.string() + ":" + std::to_string(row.line_number), "scan",
                             std::to_string(row.scan) + " is beyond the run's " +
                                 std::to_string(scans) + " scans (0.." + std::to_string(scans - 1) +
                                 ")");
    }
    std::size_t e = 0;
    while (e < scores.size() && scores[e].name != row.extractor) ++e;
    if (e == scores.size()) {
      scores.push_back({row.extractor, {}, 0.0, {}});
      found.emplace_back(run.scans.size());
    }
    found[e][row.scan].push_back(row.segment);
  }
  // After every row's scan is known to exist: a row beyond the run is named as such first.
  for (const LinesCsvRow& row : rows) RequireNearItsScansReturns(row, run.scans[row.scan], file);
  RequireNoRepeatedRow(rows, file);
  for (std::size_t e = 0; e < scores.size(); ++e) {
    for (std::size_t s = 0; s < run.scans.size(); ++s) {
      scores[e].score.Add(ScoreScanLines(found[e][s], run.scans[s], run.lines.scoring));
    }
  }

  ScoreReport report;
  SetLineMetrics(scores, scans, report.metrics, (run_dir / "laser_scans.csv").string());
  char line[512];
  std::snprintf(line, sizeof(line), "%-18s %s: %ld laser scans, range cut %s m\n", "run",
                run_dir.c_str(), scans, sim::FormatNumber(run.lines.range_cut_m).c_str());
  report.table += line;
  std::snprintf(line, sizeof(line), "%-18s %s: %zu segments\n", "file", file.c_str(), rows.size());
  report.table += line;
  std::snprintf(line, sizeof(line), "%-18s %8s %9s %10s %15s %15s %14s\n", "extractor", "recall",
                "precision", "sigma_r_m", "sigma_alpha_deg", "points_per_line", "lines_per_scan");
  report.table += line;
  for (const ExtractorScore& s : scores) {
    std::snprintf(
        line, sizeof(line), "%-18s %8.4f %9.4f %s %s %s %14.2f\n", s.name.c_str(), s.score.Recall(),
        s.score.Precision(), PrintedFigure(s.score.SigmaRM(), "%10.5f").c_str(),
        PrintedFigure(s.score.SigmaAlphaDeg(), "%15.4f").c_str(),
        PrintedFigure(s.score.PointsPerLine(), "%15.2f").c_str(),
        scans ? static_cast<double>(s.score.extracted) / static_cast<double>(scans) : 0.0);
    report.table += line;
  }
  return report;
}

}  // namespace plywood::eval
