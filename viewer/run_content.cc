#include "viewer/run_content.h"

#include <cmath>
#include <numbers>

#include "eval/geometric_map/geometric_map_run.h"
#include "eval/lines/line_scan_scorer.h"
#include "msgs/angle_units.h"
#include "perception/geometric_map/geometric_mapper.h"
#include "perception/sonar_map/sonar_explorer.h"
#include "render/overlay.h"

namespace plywood::viewer {
namespace {

double SiteHeight(const sim::Scene& scene, const std::string& name, double fallback) {
  const std::optional<int> site = scene.FindSite(name);
  return site ? scene.SiteHeightM(*site) : fallback;
}

PathView Path(const std::string& label, render::Rgb colour) {
  PathView path;
  path.label = label;
  path.rgba[0] = colour.r / 255.0f;
  path.rgba[1] = colour.g / 255.0f;
  path.rgba[2] = colour.b / 255.0f;
  return path;
}

// The lines the experiment's first extractor finds in `record`, in the world frame.
std::vector<SegmentView> ExtractLines(const sim::ExperimentRunner& runner,
                                      const sim::LaserRecord& record) {
  sim::LinesConfig lines = runner.config().lines;
  if (lines.extractors.empty()) return {};
  lines.extractors.resize(1);
  const sim::LaserRecord* records[] = {&record};
  const eval::TruthScan scan =
      eval::MakeTruthScan(records, runner.record().walls, lines.range_cut_m);
  const std::vector<eval::ExtractorScore> scores =
      eval::ScoreExtractors(std::span<const eval::TruthScan>(&scan, 1), lines);
  std::vector<SegmentView> out;
  if (scores.empty() || scores.front().scans.empty()) return out;
  const eval::ScanLines& found = scores.front().scans.front();
  const msgs::Pose2D X_WS = record.X_WR_truth * record.scan.X_RS;
  const auto to_world = [&](const Eigen::Vector2d& p_S) {
    const msgs::Pose2D p = X_WS * msgs::Pose2D{p_S.x(), p_S.y(), 0.0};
    return Eigen::Vector2d(p.x_m, p.y_m);
  };
  for (std::size_t i = 0; i < found.segments.size(); ++i) {
    out.push_back({to_world(found.segments[i].start), to_world(found.segments[i].end),
                   found.matched_truth[i] >= 0});
  }
  return out;
}

// The explorer's cognitive map now (partitions, and the graph's arcs through their doors).
MapView ExplorerMap(const perception::SonarExplorer& explorer) {
  const perception::CognitiveMap map = explorer.Map();
  MapView view;
  const auto& partitions = map.partitions.partitions();
  for (const perception::Partition& p : partitions) {
    view.partitions.push_back(
        {{p.rect.x0, p.rect.y0}, {p.rect.x1, p.rect.y1}, p.label == perception::Label::kFree});
  }
  for (const perception::Adjacency& arc : map.graph.arcs) {
    const Eigen::Vector2d door = 0.5 * (arc.door_a + arc.door_b);
    view.graph_arcs.emplace_back(partitions[arc.a].rect.Centre(), door);
    view.graph_arcs.emplace_back(door, partitions[arc.b].rect.Centre());
  }
  return view;
}

// The explorer's occupancy grid now.
GridView ExplorerGrid(const perception::SonarExplorer& explorer) {
  const perception::LogOddsGrid& grid = explorer.grid();
  GridView view;
  view.cell_00_centre_W = grid.CellCentre(0, 0);
  view.cell_m = grid.resolution_m();
  view.width = grid.width();
  view.height = grid.height();
  view.occupied_p.reserve(static_cast<std::size_t>(view.width) * view.height);
  for (int iy = 0; iy < view.height; ++iy) {
    for (int ix = 0; ix < view.width; ++ix) {
      view.occupied_p.push_back(static_cast<float>(grid.Probability(ix, iy)));
    }
  }
  return view;
}

GeometricMapView MapSegments(const perception::GeometricMap& map) {
  GeometricMapView view;
  for (const perception::MapSegment& s : map.segments()) {
    // What geometric_map.png shows: confirmed real segments and pseudo ones.
    if (s.pseudo || map.Confirmed(s)) view.segments.push_back({s.line.start, s.line.end, s.pseudo});
  }
  for (const perception::MapCluster& c : map.clusters()) {
    view.clusters.emplace_back(c.box.min(), c.box.max());
  }
  return view;
}

}  // namespace

std::vector<RingReadingKind> ClassifyRing(const sim::Scene& scene, const msgs::Pose2D& X_WR,
                                          double height_m, const msgs::RangeRing& ring) {
  mjtByte groups[mjNGROUP];
  for (int i = 0; i < mjNGROUP; ++i) groups[i] = i != sim::Scene::kRobotGeomGroup;
  std::vector<RingReadingKind> kinds;
  for (const msgs::RangeReading& r : ring.readings) {
    const msgs::Pose2D X_WS = X_WR * r.X_RS;
    const mjtNum origin[3] = {X_WS.x_m, X_WS.y_m, height_m};
    const mjtNum direction[3] = {std::cos(X_WS.theta_rad), std::sin(X_WS.theta_rad), 0.0};
    int geom = -1;
    const double truth =
        mj_ray(scene.model(), scene.data(), origin, direction, groups, 1, -1, &geom);
    const bool wall_in_range = geom >= 0 && truth >= 0.0 && truth < ring.range_max_m;
    // Off-axis surfaces inside the cone legitimately echo nearer than the axis ray.
    const double tolerance = std::max(0.15, 0.1 * truth);
    if (r.echo) {
      kinds.push_back(!wall_in_range || r.range_m > truth + tolerance ? RingReadingKind::kMultipath
                                                                      : RingReadingKind::kEcho);
    } else {
      kinds.push_back(wall_in_range ? RingReadingKind::kSpecularMiss : RingReadingKind::kNothing);
    }
  }
  return kinds;
}

RunContent::RunContent(const sim::ExperimentRunner& runner) {
  const sim::Scene& scene = runner.scene();
  laser_height_m_ = SiteHeight(scene, "laser", 0.3);
  sonar_height_m_ = SiteHeight(scene, "sonar_0", 0.2);
  ir_height_m_ = SiteHeight(scene, "ir_0", 0.1);
  content_.paths.push_back(Path("ground truth", render::colours::kBlack));
  if (runner.config().geometric_map.given) {
    geometric_mapper_ =
        std::make_unique<perception::GeometricMapper>(runner.config().geometric_map.options);
  }
  const auto& names = runner.record().estimator_names;
  for (std::size_t e = 0; e < names.size(); ++e) {
    content_.paths.push_back(
        Path(names[e], render::colours::kPalette[e % std::size(render::colours::kPalette)]));
  }
}

const FrameContent& RunContent::Update(const sim::ExperimentRunner& runner) {
  const sim::RunRecord& record = runner.record();
  const sim::ExperimentConfig& config = runner.config();
  content_.time_s = runner.scene().time_s();
  for (; trajectory_seen_ < record.trajectory.size(); ++trajectory_seen_) {
    const sim::TrajectorySample& s = record.trajectory[trajectory_seen_];
    content_.paths[0].points_W.emplace_back(s.truth.x_m, s.truth.y_m);
    for (std::size_t e = 0; e < s.estimates.size(); ++e) {
      content_.paths[e + 1].points_W.emplace_back(s.estimates[e].x_m, s.estimates[e].y_m);
    }
  }
  if (record.laser.size() != laser_seen_ && !record.laser.empty()) {
    laser_seen_ = record.laser.size();
    const sim::LaserRecord& last = record.laser.back();
    LaserView view;
    view.X_WS = last.X_WR_truth * last.scan.X_RS;
    view.height_m = laser_height_m_;
    view.range_max_m = last.scan.range_max_m;
    view.ranges_m = last.scan.ranges_m;
    for (std::size_t i = 0; i < last.scan.ranges_m.size(); ++i) {
      view.angles_rad.push_back(last.scan.BeamAngleRad(i));
    }
    content_.laser = std::move(view);
    if (config.lines.given) content_.lines = ExtractLines(runner, last);
  }
  // Rings carry no pose: they were read during the step just taken, at about the current pose.
  const msgs::Pose2D X_WR = runner.scene().TruePose();
  if (record.sonar.size() != sonar_seen_ && !record.sonar.empty()) {
    sonar_seen_ = record.sonar.size();
    RingView view{X_WR,
                  sonar_height_m_,
                  config.sensors.sonar->beam_half_angle_deg * kDegToRad,
                  record.sonar.back(),
                  {}};
    view.kinds = ClassifyRing(runner.scene(), X_WR, sonar_height_m_, view.ring);
    content_.sonar = std::move(view);
  }
  // Seed 001's map, rebuilt from the explorer's grid once per simulated second (it is not free).
  const auto* explorer = dynamic_cast<const perception::SonarExplorer*>(runner.controller());
  if (explorer && content_.time_s >= next_map_s_) {
    next_map_s_ = content_.time_s + 1.0;
    content_.map = ExplorerMap(*explorer);
    content_.grid = ExplorerGrid(*explorer);
  }
  // Seed 003's map, grown scan by scan as eval/geometric_map builds it after the run: each IR scan
  // with the sonar ring nearest in time, once every ring that could be nearest has been read.
  if (geometric_mapper_ && record.ir_scanner.size() != ir_scans_seen_) {
    const double max_age_s = config.geometric_map.max_sonar_age_s;
    const bool ended = content_.time_s >= config.duration_s - 1e-9;
    bool added = false;
    for (; ir_scans_seen_ < record.ir_scanner.size(); ++ir_scans_seen_) {
      const sim::LaserRecord& ir = record.ir_scanner[ir_scans_seen_];
      if (!ended && content_.time_s < ir.scan.time_s + max_age_s) break;
      const msgs::RangeRing* sonar =
          eval::NearestSonarRing(record.sonar, ir.scan.time_s, max_age_s, &next_sonar_);
      geometric_mapper_->AddScan(ir.scan, sonar, ir.X_WR_odometry);
      added = true;
    }
    if (added) content_.geometric_map = MapSegments(geometric_mapper_->map());
  }
  if (record.ir_ring.size() != ir_seen_ && !record.ir_ring.empty()) {
    ir_seen_ = record.ir_ring.size();
    content_.ir = RingView{X_WR, ir_height_m_, 0.0, record.ir_ring.back(), {}};
  }
  return content_;
}

}  // namespace plywood::viewer
