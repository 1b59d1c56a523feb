#include "eval/lines/log_replay_run.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "msgs/shortest_number.h"
#include "perception/lines/line_extractor_factory.h"
#include "perception/lines/scan_points.h"
#include "perception/lines/what_each_line_needs.h"
#include "perception/logs/carmen_log.h"
#include "perception/logs/regular_file.h"
#include "render/overlay.h"
#include "render/png_image.h"
#include "render/world_to_pixel.h"
#include "sim/config/config_error.h"
#include "sim/config/lines_config.h"
#include "sim/config/yaml_fields.h"
#include "sim/config/yaml_nul_characters.h"
#include "sim/runner/json_text.h"
#include "sim/runner/metrics.h"
#include "sim/runner/run_directory.h"
#include "sim/runner/text_file.h"

namespace plywood::eval {
namespace {

// The record of the replay, so its directory is recognisable as a run (sim::HoldsPlywoodRun).
std::string ReplayConfigYaml(const LogReplayRequest& request, const std::string& name,
                             sim::LinesConfig lines) {
  lines.extractors = {request.extractor};
  YAML::Node root(YAML::NodeType::Map);
  root["name"] = name;
  root["replay"]["log"] = std::filesystem::absolute(request.log).string();
  root["replay"]["extractor"] = request.extractor;
  root["replay"]["skip_bad"] = request.skip_bad;
  root["lines"] = sim::WriteLinesConfig(lines);
  YAML::Emitter out;
  out << root;
  return std::string(out.c_str()) + "\n";
}

void WriteSegmentsPicture(const perception::CarmenLog& log, const perception::ReplayResult& result,
                          const std::filesystem::path& path) {
  // The segments of every scan, placed by the logged laser poses, on a white page.
  render::WorldBounds bounds = render::WorldBounds::Empty();
  for (const auto& [a, b] : result.segments_W) bounds.Extend(a), bounds.Extend(b);
  for (const auto& record : log.lasers)
    bounds.Extend(Eigen::Vector2d(record.X_WL.x_m, record.X_WL.y_m));
  if (bounds.IsEmpty() || bounds.width_m() + bounds.height_m() <= 0.0) return;
  const render::TopDownFrame frame = render::FrameBounds(bounds.Padded(1.0), 1600);
  render::RgbImage image(frame.width_px, frame.height_px);
  render::Fill(image, render::colours::kWhite);
  for (const auto& [a, b] : result.segments_W)
    render::DrawSegment(image, frame.world_to_pixel, a, b, render::colours::kBlue, 1.0);
  for (const auto& record : log.lasers)
    render::DrawPoint(image, frame.world_to_pixel, {record.X_WL.x_m, record.X_WL.y_m},
                      render::colours::kRed, 1.0);
  render::WritePng(image, path);
}

// The replay runs one extractor and reads nothing else of `lines:`: a --set of another extractor
// (or of range_cut_m, scoring, extractors) would be dropped without a word.
void RequireOptionsOfTheExtractorRun(const LogReplayRequest& request) {
  for (const std::string& assignment : request.overrides) {
    const std::string key = assignment.substr(0, assignment.find('='));
    const std::string section = key.substr(0, key.find('.'));
    if (section == request.extractor) continue;
    throw sim::ConfigError("--set", key,
                           "the replay runs only '" + request.extractor +
                               "' (--extractor) and reads only its options (" + request.extractor +
                               ".KEY=VALUE): this one would be ignored");
  }
}

// A line is drawn from the points of one scan: a --set count above the points of the log's
// fullest scan finds no line in any scan, and the replay reported rays_explained 0, exit 0 (s57's
// left item). Only counts the user set: a default above a log's sparse scans is the extractor's
// own limit. The points are those the replay gives the extractor (returns within range).
void RequireCountsTheScansCanMeet(const LogReplayRequest& request, const YAML::Node& lines_node,
                                  const perception::LineExtractorOptions& options,
                                  const perception::CarmenLog& log) {
  // Set by the user: under the extractor in the node the --sets built (it starts empty), so a
  // whole mapping (`--set 'split_and_merge={min_points: 1000}'`) counts as its key does (s61).
  const YAML::Node extractor_node = lines_node[request.extractor];
  const auto user_set = [&](const std::string& key) {
    return extractor_node.IsMap() && extractor_node[key].IsDefined();
  };
  std::vector<std::pair<std::string, int>> counts;
  for (const auto& [key, count] : perception::PointsEachLineNeeds(options, request.extractor)) {
    if (user_set(key)) counts.emplace_back(request.extractor + "." + key, count);
  }
  // The same for a minimum length above twice the farthest return (no two points of a scan lie
  // farther apart): min_length_m 1e300 gave rays_explained 0, exit 0 (s60).
  const std::string length_key = request.extractor + ".min_length_m";
  const bool length_set = user_set("min_length_m");
  if (counts.empty() && !length_set) return;
  std::size_t points = 0;
  double farthest_m = 0.0;
  for (const auto& record : log.lasers) {
    const perception::ScanPoints scan = perception::MakeScanPoints(
        record.scan, perception::ScanFilter::ForLog(record.scan.range_max_m));
    points = std::max(points, scan.points.size());
    for (const auto& point : scan.points) farthest_m = std::max(farthest_m, point.norm());
  }
  const double shortest_m = perception::ShortestLineKeptM(options, request.extractor);
  if (length_set && shortest_m > 2.0 * farthest_m) {
    throw sim::ConfigError("--set", length_key,
                           msgs::ShortestNumber(shortest_m) +
                               " m is more than twice the farthest return (within range) in " +
                               request.log.string() + ", " + msgs::ShortestNumber(farthest_m) +
                               " m: no two points of a scan lie farther apart, so no line could "
                               "be found");
  }
  for (const auto& [dotted, count] : counts) {
    if (static_cast<std::size_t>(count) <= points) continue;
    throw sim::ConfigError("--set", dotted,
                           std::to_string(count) + " is more than the " + std::to_string(points) +
                               " points (returns within range) of the fullest scan in " +
                               request.log.string() +
                               ": a line is drawn from one scan's points, so none could be "
                               "found; give at most " +
                               std::to_string(points));
  }
}

}  // namespace

std::filesystem::path DefaultReplayDirectory(const std::filesystem::path& log,
                                             const std::string& extractor) {
  return "runs/replay-" + log.filename().string() + "-" + extractor;
}

LogReplaySummary RunLogReplay(const LogReplayRequest& request) {
  // --set assignments read like an experiment's `lines:` section (ConfigError naming the key).
  YAML::Node lines_node(YAML::NodeType::Map);
  for (const std::string& assignment : request.overrides) {
    sim::ApplyOverride(lines_node, assignment, "--set " + assignment);
  }
  sim::RejectNulCharacters(lines_node, "--set");  // an error naming the value cut it at the NUL
  sim::LinesConfig lines;
  sim::ReadLinesConfig(sim::YamlFields(lines_node, "--set", ""), lines);
  RequireOptionsOfTheExtractorRun(request);
  const auto extractor = perception::MakeLineExtractor(request.extractor, lines.options);
  perception::CarmenReadOptions read_options;
  read_options.skip_bad = request.skip_bad;
  perception::CarmenLog log;
  try {
    log = perception::ReadCarmenLog(request.log, read_options);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());  // a malformed log is bad input: one line, exit 2
  }
  RequireCountsTheScansCanMeet(request, lines_node, lines.options, log);
  LogReplaySummary summary;
  summary.out_dir = request.out_dir.empty() ? DefaultReplayDirectory(request.log, request.extractor)
                                            : request.out_dir;
  // `replay RUN/laser.log --out RUN --force` read the log, then replaced the run folder with the
  // replay's files: the log, and the run it came from, were deleted (s56). Without --force the
  // folder is refused already (an earlier run, or files that are not one).
  std::error_code error;
  if (request.force && std::filesystem::is_directory(summary.out_dir, error) &&
      std::filesystem::weakly_canonical(request.log, error).parent_path() ==
          std::filesystem::weakly_canonical(summary.out_dir, error)) {
    throw sim::ConfigError(summary.out_dir.string(), "",
                           "holds " + request.log.filename().string() +
                               ", the log being replayed: --force would delete it with the run "
                               "it came from; choose another --out");
  }
  sim::StagedRunDirectory staged(summary.out_dir, request.force);
  const std::filesystem::path& dir = staged.staging();
  summary.skipped_lines = log.skipped_lines;
  summary.result = perception::ReplayLog(log, *extractor);
  const perception::ReplayResult& result = summary.result;
  if (result.rays.rays == 0) {
    // Every range 0 or at the maximum (say all 1 m without PARAM front_laser_max, which makes 1 m
    // the maximum): rays_explained would read 0 of 0 (fuzz30). Nothing is written.
    throw std::invalid_argument(request.log.string() +
                                ": no valid ray (a range above 0 and below " +
                                "the maximum range) in the log's " + std::to_string(result.scans) +
                                (result.scans == 1 ? " scan" : " scans") +
                                ": rays_explained is undefined, nothing to score");
  }

  sim::WriteTextFile(
      dir / "config.yaml",
      ReplayConfigYaml(request,
                       DefaultReplayDirectory(request.log, request.extractor).filename().string(),
                       lines));
  sim::Metrics metrics;
  metrics.Set("replay.extractor", request.extractor);
  metrics.Set("replay.scans", static_cast<double>(result.scans));
  metrics.Set("replay.skipped_lines", static_cast<double>(log.skipped_lines));
  metrics.Set("replay.valid_rays", static_cast<double>(result.rays.rays));
  metrics.Set("replay.lines", static_cast<double>(result.lines));
  metrics.Set("replay.rays_explained", result.rays.Fraction());
  metrics.Set("replay.rms_m", result.rays.RmsM());
  metrics.Set("replay.rays_per_line", result.RaysPerLine());
  metrics.Set("replay.lines_per_scan", result.LinesPerScan());
  metrics.Set("replay.circles", static_cast<double>(result.circles));
  metrics.Set("replay.circles_per_scan", result.CirclesPerScan());
  metrics.Set("replay.rays_explained_with_circles", result.rays_with_circles.Fraction());
  metrics.Set("replay.rms_with_circles_m", result.rays_with_circles.RmsM());
  sim::WriteTextFile(dir / "metrics.json", metrics.ToJson());
  sim::WriteTextFile(
      dir / "timing.json",
      sim::WriteJson(nlohmann::ordered_json{{"replay", {{"us_per_scan", result.UsPerScan()}}}},
                     {.layout = sim::JsonStyle::Layout::kOneLine}));
  std::string scans = "scan,valid_rays,explained,lines,explained_with_circles,circles\n";
  for (std::size_t k = 0; k < result.per_scan.size(); ++k) {
    const perception::ReplayResult::Scan& scan = result.per_scan[k];
    scans += std::to_string(k) + "," + std::to_string(scan.valid_rays) + "," +
             std::to_string(scan.explained) + "," + std::to_string(scan.lines) + "," +
             std::to_string(scan.explained_with_circles) + "," + std::to_string(scan.circles) +
             "\n";
  }
  sim::WriteTextFile(dir / "scans.csv", scans);
  std::string circles = "scan,x_m,y_m,radius_m,rms_m,points\n";
  for (const auto& [scan, circle] : result.circles_L) {
    circles += std::to_string(scan) + "," + msgs::ShortestNumber(circle.centre.x()) + "," +
               msgs::ShortestNumber(circle.centre.y()) + "," +
               msgs::ShortestNumber(circle.radius_m) + "," + msgs::ShortestNumber(circle.rms_m) +
               "," + std::to_string(circle.num_points()) + "\n";
  }
  sim::WriteTextFile(dir / "circles.csv", circles);
  WriteSegmentsPicture(log, result, dir / "segments.png");
  staged.Commit();
  return summary;
}

}  // namespace plywood::eval
