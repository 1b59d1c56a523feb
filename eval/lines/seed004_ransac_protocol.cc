#include "eval/lines/seed004_ransac_protocol.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "eval/lines/lines_csv.h"
#include "eval/printed_figure.h"
#include "perception/lines/line_scoring.h"
#include "perception/lines/ransac_extractor.h"
#include "render/overlay.h"
#include "render/png_image.h"
#include "render/world_to_pixel.h"
#include "sim/config/config_archive.h"
#include "sim/config/config_error.h"
#include "sim/config/lines_config.h"
#include "sim/config/lines_fields.h"
#include "sim/config/yaml_fields.h"
#include "sim/runner/experiment_runner.h"
#include "sim/runner/text_file.h"

namespace plywood::eval {
namespace {

struct Cloud {
  std::vector<Eigen::Vector2d> points_W;
  std::vector<int> hit_segment;  // per point: wall face hit, -1 for legs, columns ...
};

Cloud Accumulate(const sim::RunRecord& record, bool odometry, int scan_stride, int beam_stride) {
  Cloud cloud;
  for (std::size_t k = 0; k < record.laser.size(); k += scan_stride) {
    const sim::LaserRecord& laser = record.laser[k];
    const msgs::Pose2D X_WS = (odometry ? laser.X_WR_odometry : laser.X_WR_truth) * laser.scan.X_RS;
    for (std::size_t i = 0; i < laser.scan.ranges_m.size(); i += beam_stride) {
      if (!laser.scan.IsReturn(i)) continue;
      const double r = laser.scan.ranges_m[i];
      const double a = X_WS.theta_rad + laser.scan.BeamAngleRad(i);
      cloud.points_W.emplace_back(X_WS.x_m + r * std::cos(a), X_WS.y_m + r * std::sin(a));
      cloud.hit_segment.push_back(laser.hit_segment_ids[i]);
    }
  }
  return cloud;
}

// The `seed004_ransac:` section: scan_stride, beam_stride and ransac: {...}.
struct Seed004RansacOptions {
  int scan_stride = 5, beam_stride = 4;
  perception::RansacOptions ransac;
};

// @throws sim::ConfigError naming the field.
Seed004RansacOptions ReadSeed004RansacOptions(const sim::ExperimentConfig& config) {
  Seed004RansacOptions options;
  options.ransac.min_inliers = 150;
  options.ransac.min_points = 100;
  options.ransac.max_lines = 200;
  sim::YamlFields fields(config.protocol_options, config.source_file, config.protocol);
  fields.Get("scan_stride", &options.scan_stride);
  fields.Get("beam_stride", &options.beam_stride);
  if (options.scan_stride < 1) fields.Fail("scan_stride", "must be >= 1");
  if (options.beam_stride < 1) fields.Fail("beam_stride", "must be >= 1");
  sim::YamlReadArchive archive(fields.Child("ransac"));
  VisitFields(archive, options.ransac);
  archive.fields().Finish();
  archive.fields().Validate(options.ransac);
  fields.Finish();
  // The odometry cloud places each scan at the record's odometry pose, which a run without an
  // estimator fills with the true pose: its "odometry" lines were the truth's, exit 0 (s49).
  sim::RequireOdometryEstimator(config, "odometry",
                                "seed004_ransac accumulates its odometry cloud");
  return options;
}

}  // namespace

void CheckSeed004RansacOptions(const sim::ExperimentConfig& config) {
  ReadSeed004RansacOptions(config);
}

int Seed004RansacProtocol(const ProtocolContext& context) {
  sim::ExperimentConfig config = context.config;
  const Seed004RansacOptions options = ReadSeed004RansacOptions(config);
  const int scan_stride = options.scan_stride, beam_stride = options.beam_stride;
  const perception::RansacOptions& ransac = options.ransac;
  if (!config.sensors.laser) {
    throw sim::ConfigError(config.source_file, "sensors.laser", "missing: the cloud needs a laser");
  }
  config.protocol = "single";
  sim::ExperimentRunner runner(config);
  runner.Run();
  const sim::RunRecord& record = runner.record();
  const std::filesystem::path out = context.out_dir;
  std::filesystem::create_directories(out);
  const perception::RansacExtractor extractor(ransac);
  sim::Metrics metrics;
  std::vector<LinesCsvRow> line_rows;  // lines.csv: the whole run is scan 0, in the world frame
  for (const bool odometry : {false, true}) {
    const std::string name = odometry ? "odometry" : "truth";
    const Cloud cloud = Accumulate(record, odometry, scan_stride, beam_stride);
    std::vector<std::vector<int>> inliers;
    const auto lines = extractor.ExtractFromPoints(cloud.points_W, &inliers);
    // Scored against the wall surfaces (faces continuing one another joined), each named in the
    // csv files by its longest face (sim::WallSurface::name).
    const std::vector<sim::WallSurface>& surfaces = record.walls.surfaces;
    std::vector<perception::TruthSegment> truth(surfaces.size());
    for (std::size_t k = 0; k < truth.size(); ++k) {
      truth[k].a = surfaces[k].a;
      truth[k].b = surfaces[k].b;
    }
    for (int s : cloud.hit_segment)
      if (s >= 0) ++truth[record.walls.surface_of_segment[s]].observed_rays;
    perception::LineScoringOptions scoring;
    scoring.min_observed_rays = ransac.min_points;  // faces with enough cloud points to be a line
    const perception::LineScore score =
        perception::ScoreScan(lines, truth, static_cast<long>(cloud.points_W.size()), scoring);
    // No face with min_points of the cloud (s54: `scan_stride: 1e9` left 89 points): recall and
    // precision read 1 over nothing, sigmas 0, exit 0. The faces are the same in both clouds.
    if (score.observable == 0) {
      throw sim::ConfigError(
          config.source_file, "seed004_ransac",
          "no wall surface holds ransac.min_points (" + std::to_string(ransac.min_points) +
              ") of the " + name + " cloud's " + std::to_string(cloud.points_W.size()) +
              " points (scan_stride " + std::to_string(scan_stride) + ", beam_stride " +
              std::to_string(beam_stride) + "): recall is undefined, nothing to score against");
    }
    if (!context.quiet && !odometry)  // after the check: a refused cloud prints nothing
      std::printf("\nseed 004 RANSAC on the accumulated cloud (%s)\n", config.name.c_str());
    int false_lines = 0, false_on_legs = 0;
    std::string csv =
        "line,alpha_rad,r_m,ax_m,ay_m,bx_m,by_m,points,matched_face,non_wall_fraction\n";
    std::vector<bool> matched(lines.size());
    for (std::size_t l = 0; l < lines.size(); ++l) {
      const int match = perception::MatchSegment(lines[l], truth, scoring);
      const int face = match < 0 ? -1 : surfaces[match].name;
      matched[l] = face >= 0;
      line_rows.push_back({"", 0, name, lines[l], face, 0});
      int non_wall = 0;
      for (int i : inliers[l]) non_wall += cloud.hit_segment[i] < 0;
      const double fraction = inliers[l].empty() ? 0.0 : double(non_wall) / inliers[l].size();
      if (face < 0) {
        ++false_lines;
        false_on_legs += fraction > 0.5;
      }
      csv += std::to_string(l) + "," + sim::FormatNumber(lines[l].alpha_rad) + "," +
             sim::FormatNumber(lines[l].r_m) + "," + sim::FormatNumber(lines[l].start.x()) + "," +
             sim::FormatNumber(lines[l].start.y()) + "," + sim::FormatNumber(lines[l].end.x()) +
             "," + sim::FormatNumber(lines[l].end.y()) + "," + std::to_string(lines[l].num_points) +
             "," + std::to_string(face) + "," + sim::FormatNumber(fraction) + "\n";
    }
    const std::string key = "seed004." + name + ".";
    metrics.Set(key + "points", static_cast<double>(cloud.points_W.size()));
    metrics.Set(key + "lines", static_cast<double>(lines.size()));
    metrics.Set(key + "recall", score.Recall());
    metrics.Set(key + "precision", score.Precision());
    metrics.Set(key + "sigma_r_m", score.SigmaRM());
    metrics.Set(key + "sigma_alpha_deg", score.SigmaAlphaDeg());
    metrics.Set(key + "false_lines", false_lines);
    metrics.Set(key + "false_lines_on_legs", false_on_legs);
    sim::WriteTextFile(out / ("lines_" + name + ".csv"), csv);

    if (context.snapshots) {
      render::WorldBounds bounds = render::WorldBounds::Empty();
      for (const auto& s : record.walls.segments) bounds.Extend(s.a), bounds.Extend(s.b);
      const render::TopDownFrame frame = render::FrameBounds(bounds.Padded(0.5), 1600);
      render::RgbImage image(frame.width_px, frame.height_px);
      render::Fill(image, render::colours::kWhite);
      for (const auto& p : cloud.points_W)
        render::DrawPoint(image, frame.world_to_pixel, p, render::Rgb{170, 170, 170}, 0.8);
      for (const auto& s : record.walls.segments)
        render::DrawSegment(image, frame.world_to_pixel, s.a, s.b, render::colours::kBlack, 1.0);
      for (std::size_t l = 0; l < lines.size(); ++l)
        render::DrawSegment(image, frame.world_to_pixel, lines[l].start, lines[l].end,
                            matched[l] ? render::colours::kBlue : render::colours::kRed, 3.0);
      render::WritePng(image, out / ("cloud_" + name + ".png"));
    }
    if (!context.quiet) {
      std::printf(
          "%-9s %7zu points  %3zu lines  recall %.3f  precision %.3f  sigma_r %s  "
          "false %d (%d on legs/columns)\n",
          name.c_str(), cloud.points_W.size(), lines.size(), score.Recall(), score.Precision(),
          PrintedFigure(score.SigmaRM(), "%.4f", "m").c_str(), false_lines, false_on_legs);
    }
  }
  WriteLinesCsv(out / "lines.csv", line_rows);
  sim::WriteTextFile(out / "config.yaml", sim::ExperimentConfigToYaml(context.config));
  sim::WriteTextFile(out / "metrics.json", metrics.ToJson());
  return 0;
}

}  // namespace plywood::eval
