#include "eval/lines/seed000_protocol.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "eval/lines/lines_csv.h"
#include "eval/lines/seed000_rooms.h"
#include "eval/printed_figure.h"
#include "eval/score/csv_table.h"
#include "msgs/shortest_number.h"
#include "render/overlay.h"
#include "render/png_image.h"
#include "render/world_to_pixel.h"
#include "sim/config/config_error.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/text_file.h"

namespace plywood::eval {
namespace {

// Ground-truth faces (grey; observed ones black), the first scan pair's points (red), the first
// extractor's segments on it (blue) and the round objects of the spot (magenta), in the world
// frame (= the front sensor's frame).
void WriteRoomPicture(const eval::Seed000RoomResult& result, const sim::LinesConfig& lines,
                      const std::filesystem::path& path) {
  if (result.scans.empty()) return;
  const eval::TruthScan& scan = result.scans.front();
  render::WorldBounds bounds = render::WorldBounds::Empty();
  for (const auto& p : scan.points.points) bounds.Extend(p);
  bounds.Extend(Eigen::Vector2d::Zero());
  if (bounds.IsEmpty() || bounds.width_m() + bounds.height_m() <= 0.0) return;
  const render::TopDownFrame frame = render::FrameBounds(bounds.Padded(0.5), 900);
  render::RgbImage image(frame.width_px, frame.height_px);
  render::Fill(image, render::colours::kWhite);
  for (const auto& t : scan.truth) {
    const bool seen = t.observed_rays >= lines.scoring.min_observed_rays;
    render::DrawSegment(image, frame.world_to_pixel, t.a, t.b,
                        seen ? render::colours::kBlack : render::Rgb{190, 190, 190},
                        seen ? 3.0 : 1.0);
  }
  for (const auto& p : scan.points.points)
    render::DrawPoint(image, frame.world_to_pixel, p, render::colours::kRed, 1.5);
  // The first extractor's lines as they were scored (the spot's round objects' chords left out),
  // and those round objects in magenta.
  if (!result.scores.empty() && !result.scores.front().scans.empty()) {
    for (const auto& s : result.scores.front().scans.front().segments)
      render::DrawSegment(image, frame.world_to_pixel, s.start, s.end, render::colours::kBlue, 2.0);
  }
  for (const perception::CircleFeature& c : result.spot_round_objects) {
    render::DrawCircle(image, frame.world_to_pixel, c.centre, c.radius_m, render::colours::kMagenta,
                       2.0);
  }
  render::DrawPoint(image, frame.world_to_pixel, Eigen::Vector2d::Zero(), render::colours::kGreen,
                    4.0);
  render::WritePng(image, path);
}

// The field that sets a room's range cut: its entry in rooms:, else the top-level range_cut_m.
std::string RangeCutField(const sim::ExperimentConfig& config,
                          const eval::Seed000RoomsOptions& options, const eval::Seed000Room& room) {
  for (std::size_t i = 0; i < options.rooms.size(); ++i) {
    if (std::filesystem::equivalent(options.rooms[i].world_path, room.world_path)) {
      return config.protocol + ".rooms[" + std::to_string(i) + "].range_cut_m";
    }
  }
  return config.protocol + ".range_cut_m";
}

// A room with no wall observable within its cut has recall 0 / 0: its figures would read 1 over
// nothing (s63), so the run is refused before any figure is printed or written.
void RefuseARoomWithNoWallInView(const sim::ExperimentConfig& config,
                                 const eval::Seed000RoomsOptions& options,
                                 const eval::Seed000RoomResult& result) {
  if (result.scores.empty() || result.scores.front().score.observable > 0) return;
  throw sim::ConfigError(
      config.source_file, RangeCutField(config, options, result.room),
      "no ground-truth wall of " + result.room.world_path.filename().string() +
          " was observable within the range cut of " +
          msgs::ShortestNumber(result.room.range_cut_m) + " m in any of the " +
          std::to_string(result.scans.size()) +
          " scan pairs (scoring.min_observed_rays returns): recall is undefined, nothing to "
          "score against; raise the cut");
}

}  // namespace

void CheckSeed000Options(const sim::ExperimentConfig& config) {
  eval::RoomsToRun(config, eval::ReadSeed000RoomsOptions(config));
}

std::vector<std::filesystem::path> Seed000OtherWorlds(const sim::ExperimentConfig& config) {
  std::vector<std::filesystem::path> worlds;
  for (const eval::Seed000Room& room :
       eval::RoomsToRun(config, eval::ReadSeed000RoomsOptions(config))) {
    if (!std::filesystem::equivalent(room.world_path, config.world_path)) {
      worlds.push_back(room.world_path);
    }
  }
  return worlds;
}

int Seed000Protocol(const ProtocolContext& context) {
  const sim::ExperimentConfig& config = context.config;
  const eval::Seed000RoomsOptions options = eval::ReadSeed000RoomsOptions(config);
  sim::LinesConfig lines = config.lines;
  if (!lines.given) lines.extractors = perception::LineExtractorNames();
  const std::vector<eval::Seed000Room> rooms = eval::RoomsToRun(config, options);
  const std::filesystem::path out = context.out_dir;
  std::filesystem::create_directories(out);

  sim::Metrics metrics;
  std::vector<eval::ExtractorScore> total;
  long total_scans = 0;
  std::vector<LinesCsvRow> line_rows;
  std::string circles_csv = CirclesCsvHeader(/*with_room=*/true);
  std::string spot_csv = "room,x_m,y_m,radius_m,rms_m,points\n";
  std::string walls_csv = "room,segment,geom_id,face,ax_m,ay_m,bx_m,by_m\n";
  std::string csv =
      "room,range_cut_m,walls_visible,paper_lines,extractor,lines_per_scan,points_per_scan,"
      "reduction,recall,precision,sigma_r_m,sigma_alpha_deg\n";
  // Every room is run and checked before the first figure is printed or written.
  std::vector<eval::Seed000RoomResult> results;
  for (const eval::Seed000Room& room : rooms) {
    results.push_back(eval::RunSeed000Room(config, room, options.scans, options.median_of_scans,
                                           options.round_objects_from_scans));
    RefuseARoomWithNoWallInView(config, options, results.back());
  }
  if (!context.quiet) {
    // rig_at: spawn stands the rig at robot.spawn, not at the world's origin.
    const bool at_spawn = !rooms.empty() && rooms.front().rig_at_spawn;
    std::printf("\nseed 000 rooms: two back-to-back LMS 200 at the %s, %d scan pairs each%s\n",
                at_spawn ? "spawn" : "origin", options.scans,
                options.round_objects_from_scans
                    ? "; chords of the round objects in the spot's median scan left out"
                    : "");
    std::printf("%-16s %5s %7s %6s %-16s %7s %9s %7s %7s\n", "room", "cut_m", "visible", "paper",
                "extractor", "lines", "reduction", "recall", "prec");
  }
  for (const eval::Seed000RoomResult& result : results) {
    const eval::Seed000Room& room = result.room;
    const std::string stem = room.world_path.stem().string();
    const std::string key = "seed000." + stem;
    for (const LinesCsvRow& row : LinesCsvRows(result.scores, stem)) line_rows.push_back(row);
    circles_csv += CirclesCsvRows(result.scores, stem);
    for (const perception::CircleFeature& c : result.spot_round_objects) {
      spot_csv += CsvField(stem) + "," + CircleCsvColumns(c) + "\n";
    }
    for (std::size_t i = 0; i < result.rig.walls.segments.size(); ++i) {
      const sim::WallSegment& w = result.rig.walls.segments[i];
      walls_csv += CsvField(stem) + "," + std::to_string(i) + "," + std::to_string(w.geom_id) +
                   "," + std::to_string(w.face_index) + "," + sim::FormatNumber(w.a.x()) + "," +
                   sim::FormatNumber(w.a.y()) + "," + sim::FormatNumber(w.b.x()) + "," +
                   sim::FormatNumber(w.b.y()) + "\n";
    }
    metrics.Set(key + ".walls_visible", result.WallsVisible());
    metrics.Set(key + ".points_per_scan", result.PointsPerScan());
    metrics.Set(key + ".range_cut_m", room.range_cut_m);
    if (room.paper_lines > 0) metrics.Set(key + ".paper_lines", room.paper_lines);
    for (const auto& s : result.scores) {
      const double lines_per_scan =
          s.score.scans ? static_cast<double>(s.score.extracted) / s.score.scans : 0.0;
      // No line, no reduction to report: null, not 0 (s63).
      const double reduction = lines_per_scan > 0 ? result.PointsPerScan() / lines_per_scan
                                                  : std::numeric_limits<double>::quiet_NaN();
      metrics.Set(key + "." + s.name + ".lines_per_scan", lines_per_scan);
      metrics.Set(key + "." + s.name + ".reduction", reduction);
      metrics.Set(key + "." + s.name + ".recall", s.score.Recall());
      metrics.Set(key + "." + s.name + ".precision", s.score.Precision());
      // Quoted as in lines.csv: a world named 'a,b.xml' shifted every column of its rows (s43).
      csv += CsvField(stem) + "," + sim::FormatNumber(room.range_cut_m) + "," +
             sim::FormatNumber(result.WallsVisible()) + "," + std::to_string(room.paper_lines) +
             "," + s.name + "," + sim::FormatNumber(lines_per_scan) + "," +
             sim::FormatNumber(result.PointsPerScan()) + "," + sim::FormatNumber(reduction) + "," +
             sim::FormatNumber(s.score.Recall()) + "," + sim::FormatNumber(s.score.Precision()) +
             "," + sim::FormatNumber(s.score.SigmaRM()) + "," +
             sim::FormatNumber(s.score.SigmaAlphaDeg()) + "\n";
      if (!context.quiet) {
        const std::string reduction_text = std::isfinite(reduction)
                                               ? PrintedFigure(reduction, "%8.1f") + "x"
                                               : PrintedFigure(reduction, "%9.1f");
        std::printf("%-16s %5.1f %7.2f %6s %-16s %7.2f %s %7.3f %7.3f\n", stem.c_str(),
                    room.range_cut_m, result.WallsVisible(),
                    room.paper_lines ? std::to_string(room.paper_lines).c_str() : "-",
                    s.name.c_str(), lines_per_scan, reduction_text.c_str(), s.score.Recall(),
                    s.score.Precision());
      }
    }
    if (total.empty()) {
      total = result.scores;
      for (auto& s : total) s.us_per_scan = 0.0;  // summed over scans below, divided at the end
    } else {
      for (std::size_t e = 0; e < total.size(); ++e) total[e].score.Add(result.scores[e].score);
    }
    for (std::size_t e = 0; e < total.size(); ++e) {
      total[e].us_per_scan +=
          result.scores[e].us_per_scan * static_cast<double>(result.scans.size());
    }
    total_scans += static_cast<long>(result.scans.size());
    if (context.snapshots) WriteRoomPicture(result, lines, out / (stem + ".png"));
  }
  for (auto& s : total) s.us_per_scan /= static_cast<double>(std::max(1L, total_scans));
  eval::SetLineMetrics(total, total_scans, metrics, config.source_file);

  sim::WriteTextFile(out / "config.yaml", sim::ExperimentConfigToYaml(config));
  sim::WriteTextFile(out / "metrics.json", metrics.ToJson());
  sim::WriteTextFile(out / "rooms.csv", csv);
  sim::WriteTextFile(out / "timing.json", eval::LineTimingJson(total));
  sim::WriteTextFile(out / "walls.csv", walls_csv);
  WriteLinesCsv(out / "lines.csv", line_rows, /*with_room=*/true);
  sim::WriteTextFile(out / "circles.csv", circles_csv);
  if (options.round_objects_from_scans) {
    sim::WriteTextFile(out / "spot_round_objects.csv", spot_csv);
  }
  if (!context.quiet) {
    std::printf("\nall rooms (%ld scan pairs)\n%-16s %7s %7s %9s %11s %9s %9s\n", total_scans,
                "extractor", "recall", "prec", "sigma_r_m", "sigma_a_deg", "pts/line", "us/scan");
    for (const auto& s : total) {
      std::printf("%-16s %7.3f %7.3f %s %s %s %9.1f\n", s.name.c_str(), s.score.Recall(),
                  s.score.Precision(), PrintedFigure(s.score.SigmaRM(), "%9.4f").c_str(),
                  PrintedFigure(s.score.SigmaAlphaDeg(), "%11.3f").c_str(),
                  PrintedFigure(s.score.PointsPerLine(), "%9.1f").c_str(), s.us_per_scan);
    }
  }
  return 0;
}

}  // namespace plywood::eval
