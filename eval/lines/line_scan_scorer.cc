#include "eval/lines/line_scan_scorer.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "perception/lines/chords_of_known_round_objects.h"
#include "perception/lines/line_extractor_factory.h"
#include "sim/config/config_error.h"
#include "sim/runner/json_text.h"

namespace plywood::eval {

TruthScan MakeTruthScan(std::span<const sim::LaserRecord* const> records,
                        const sim::GroundTruthWalls& walls, double range_cut_m) {
  std::vector<msgs::Pose2D> poses;
  for (const sim::LaserRecord* record : records) {
    poses.push_back(record->X_WR_truth * record->scan.X_RS);
  }
  return MakeTruthScanAt(records, poses, walls, range_cut_m);
}

TruthScan MakeTruthScanAt(std::span<const sim::LaserRecord* const> records,
                          std::span<const msgs::Pose2D> poses, const sim::GroundTruthWalls& walls,
                          double range_cut_m) {
  TruthScan out;
  if (records.empty()) return out;
  if (poses.size() != records.size()) throw std::invalid_argument("X_WS: one pose per record");
  if (walls.surface_of_segment.size() != walls.segments.size()) {
    throw std::invalid_argument("walls: segments not joined into surfaces (JoinContinuingFaces)");
  }
  const msgs::Pose2D X_WS0 = poses[0];
  std::vector<msgs::LaserScan> scans;
  std::vector<double> offsets;
  for (std::size_t k = 0; k < records.size(); ++k) {
    const sim::LaserRecord* record = records[k];
    const msgs::Pose2D& X_WS = poses[k];
    if (std::hypot(X_WS.x_m - X_WS0.x_m, X_WS.y_m - X_WS0.y_m) > 1e-3) {
      throw std::invalid_argument("records: combined scans must share the sensor origin");
    }
    scans.push_back(record->scan);
    offsets.push_back(X_WS.theta_rad - X_WS0.theta_rad);
  }
  const perception::ScanFilter filter{0.0, 1e18, range_cut_m};  // the scan's own limits apply too
  out.points = perception::MakeCombinedScanPoints(scans, offsets, filter);

  // Which used point hit which wall face: beam indices run over the concatenated records.
  std::vector<int> hit_segment;
  for (const sim::LaserRecord* record : records) {
    hit_segment.insert(hit_segment.end(), record->hit_segment_ids.begin(),
                       record->hit_segment_ids.end());
  }
  const msgs::Pose2D X_S0W = X_WS0.Inverse();
  out.truth.resize(walls.surfaces.size());
  out.truth_segment_ids.resize(walls.surfaces.size());
  for (std::size_t k = 0; k < walls.surfaces.size(); ++k) {
    const auto to_sensor = [&](const Eigen::Vector2d& p_W) {
      const msgs::Pose2D p = X_S0W * msgs::Pose2D{p_W.x(), p_W.y(), 0.0};
      return Eigen::Vector2d(p.x_m, p.y_m);
    };
    out.truth[k].a = to_sensor(walls.surfaces[k].a);
    out.truth[k].b = to_sensor(walls.surfaces[k].b);
    out.truth_segment_ids[k] = walls.surfaces[k].name;
  }
  // A beam on any face of a surface observes the surface.
  for (int beam : out.points.beam_index) {
    const int segment = hit_segment[beam];
    if (segment >= 0) ++out.truth[walls.surface_of_segment[segment]].observed_rays;
  }
  return out;
}

perception::LineScore ScoreScanLines(std::span<const perception::LineSegment> lines,
                                     const TruthScan& scan,
                                     const perception::LineScoringOptions& options) {
  return perception::ScoreScan(lines, scan.truth, static_cast<long>(scan.points.size()), options);
}

std::vector<ExtractorScore> ScoreExtractors(std::span<const TruthScan> scans,
                                            const sim::LinesConfig& config,
                                            const KnownRoundObjects* known) {
  std::vector<ExtractorScore> scores;
  for (const std::string& name : config.extractors) {
    const auto extractor = sim::MakeLineExtractor(name, config);
    ExtractorScore result;
    result.name = name;
    double seconds = 0.0;
    for (const TruthScan& scan : scans) {
      const auto start = std::chrono::steady_clock::now();
      perception::ExtractedFeatures features = extractor->ExtractFeatures(scan.points);
      // The extractor's own time: the rig's chord removal below is not the extractor's work.
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::vector<perception::LineSegment>& lines = features.lines;
      if (known != nullptr) {
        perception::RemoveChordsOfKnownRoundObjects(scan.points, known->circles,
                                                    known->noise_sigma_m, {}, &lines);
      }
      result.score.Add(ScoreScanLines(lines, scan, config.scoring));
      ScanLines found;
      for (const perception::LineSegment& line : lines) {
        const int match = perception::MatchSegment(line, scan.truth, config.scoring);
        found.matched_truth.push_back(match < 0 ? -1 : scan.truth_segment_ids[match]);
      }
      found.segments = std::move(lines);
      found.circles = std::move(features.circles);
      result.scans.push_back(std::move(found));
    }
    result.us_per_scan = scans.empty() ? 0.0 : 1e6 * seconds / static_cast<double>(scans.size());
    scores.push_back(std::move(result));
  }
  return scores;
}

void SetLineMetrics(std::span<const ExtractorScore> scores, long scans, sim::Metrics& metrics,
                    const std::string& source_file, const std::string& prefix) {
  // Observability is the truth's, the same for every extractor.
  if (!scores.empty() && scores.front().score.observable == 0) {
    throw sim::ConfigError(source_file, prefix,
                           "no ground-truth wall was observable in any of the " +
                               std::to_string(scans) +
                               " laser scans (scoring.min_observed_rays returns within "
                               "range_cut_m): recall is undefined, nothing to score against");
  }
  metrics.Set(prefix + ".scans", static_cast<double>(scans));
  for (const ExtractorScore& s : scores) {
    const std::string key = prefix + "." + s.name + ".";
    metrics.Set(key + "recall", s.score.Recall());
    metrics.Set(key + "precision", s.score.Precision());
    metrics.Set(key + "sigma_r_m", s.score.SigmaRM());
    metrics.Set(key + "sigma_alpha_deg", s.score.SigmaAlphaDeg());
    metrics.Set(key + "points_per_line", s.score.PointsPerLine());
    metrics.Set(key + "lines_per_scan",
                scans ? static_cast<double>(s.score.extracted) / static_cast<double>(scans) : 0.0);
  }
}

std::vector<ExtractorScore> AddLineMetrics(sim::ExperimentRunner& runner) {
  const sim::LinesConfig& config = runner.config().lines;
  sim::RunRecord& record = runner.mutable_record();
  if (!config.given || record.laser.empty()) return {};
  std::vector<TruthScan> scans;
  scans.reserve(record.laser.size());
  for (const sim::LaserRecord& laser : record.laser) {
    const sim::LaserRecord* one[] = {&laser};
    scans.push_back(MakeTruthScan(one, record.walls, config.range_cut_m));
  }
  std::vector<ExtractorScore> scores = ScoreExtractors(scans, config);
  SetLineMetrics(scores, static_cast<long>(scans.size()), record.metrics,
                 runner.config().source_file);
  return scores;
}

std::string LineTimingJson(std::span<const ExtractorScore> scores) {
  nlohmann::ordered_json lines = nlohmann::ordered_json::object();  // in the config's order
  for (const ExtractorScore& s : scores) lines[s.name]["us_per_scan"] = s.us_per_scan;
  return sim::WriteJson(nlohmann::ordered_json{{"lines", lines}},
                        {.layout = sim::JsonStyle::Layout::kOneLine});
}

}  // namespace plywood::eval
