#pragma once

#include <map>
#include <span>
#include <string>
#include <vector>

#include "perception/lines/line_extractor.h"
#include "perception/lines/line_scoring.h"
#include "perception/lines/scan_points.h"
#include "sim/config/lines_config.h"
#include "sim/runner/experiment_runner.h"

namespace plywood::eval {

// One scan as the line scorer sees it: the used points in the sensor frame (S of the first record)
// and every ground-truth wall surface (sim::WallSurface: faces continuing one another joined) in
// that frame, each with the number of used points that hit it.
struct TruthScan {
  perception::ScanPoints points;
  std::vector<perception::TruthSegment> truth;
  // The walls.csv row naming each entry of `truth`: its surface's first face.
  std::vector<int> truth_segment_ids;
};

// Builds a TruthScan from laser records taken from one spot (one record, or two back-to-back LMS
// 200 whose sensor origins coincide): a return is used when range_min_m < r < range_max_m of its
// scan and r <= range_cut_m. Poses are the ground truth ones.
// @throws std::invalid_argument when the records' sensor origins are more than 1 mm apart, or when
// `walls` has no surfaces for its segments (sim::JoinContinuingFaces not run).
TruthScan MakeTruthScan(std::span<const sim::LaserRecord* const> records,
                        const sim::GroundTruthWalls& walls, double range_cut_m);

// Same, with each record's true sensor pose X_WS given (as read back from laser_scans.csv) instead
// of computed from its X_WR_truth and scan.X_RS.
TruthScan MakeTruthScanAt(std::span<const sim::LaserRecord* const> records,
                          std::span<const msgs::Pose2D> X_WS, const sim::GroundTruthWalls& walls,
                          double range_cut_m);

// What an extractor found in one scan: its segments (sensor frame) and the walls.csv row naming the
// surface each matched (TruthScan::truth_segment_ids of perception::MatchSegment's match; -1 for
// none), for lines.csv.
struct ScanLines {
  std::vector<perception::LineSegment> segments;
  std::vector<int> matched_truth;
  std::vector<perception::CircleFeature> circles;  // the round objects it reported (circles.csv)
};

// Score of one extractor over many scans, and its wall-clock cost (never written to
// metrics.json: reruns must give the same bytes).
struct ExtractorScore {
  std::string name;
  perception::LineScore score;
  double us_per_scan = 0.0;
  std::vector<ScanLines> scans;  // in scan order
};

// Scores the segments found in one scan, as every line scorer of Plywood does: ScoreScan against
// the scan's truth, with the number of used points the extractor was given.
perception::LineScore ScoreScanLines(std::span<const perception::LineSegment> lines,
                                     const TruthScan& scan,
                                     const perception::LineScoringOptions& options);

// Round objects found in a lower-noise view of the spot every scan was taken from
// (seed000_rooms.round_objects_from_scans); `noise_sigma_m` is one scan's range noise.
struct KnownRoundObjects {
  std::vector<perception::CircleFeature> circles;
  double noise_sigma_m = 0.01;
};

// Runs each of config.extractors on every scan and scores it (perception/lines/line_scoring.h).
// With `known`, every extractor's lines that are chords of a known round object are removed from
// each scan before scoring (perception/lines/chords_of_known_round_objects.h).
std::vector<ExtractorScore> ScoreExtractors(std::span<const TruthScan> scans,
                                            const sim::LinesConfig& config,
                                            const KnownRoundObjects* known = nullptr);

// Adds lines.<extractor>.{recall, precision, sigma_r_m, sigma_alpha_deg, points_per_line,
// lines_per_scan} and lines.scans to `metrics`. A scorer never reports a number against empty
// ground truth: @throws sim::ConfigError naming `source_file` and `lines` when no ground-truth
// wall was observable in any scan (recall would be 0 / 0).
void SetLineMetrics(std::span<const ExtractorScore> scores, long scans, sim::Metrics& metrics,
                    const std::string& source_file, const std::string& prefix = "lines");

// The post-run scorer of `lines:`: every laser scan of the run, scored with the config's
// extractors; metrics into the run's record. Returns the scores (with timings) for printing, or
// nothing when the experiment has no lines section or no laser.
std::vector<ExtractorScore> AddLineMetrics(sim::ExperimentRunner& runner);

// {"lines": {"<extractor>": {"us_per_scan": ...}}} as JSON text, for timing.json.
std::string LineTimingJson(std::span<const ExtractorScore> scores);

}  // namespace plywood::eval
