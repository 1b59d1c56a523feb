#include "eval/geometric_map/geometric_map_run.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <numbers>

#include "msgs/angle_units.h"
#include "perception/lines/line_scoring.h"
#include "render/overlay.h"
#include "render/png_image.h"
#include "render/world_to_pixel.h"
#include "sim/config/config_error.h"
#include "sim/runner/format_number.h"
#include "sim/runner/json_text.h"
#include "sim/runner/text_file.h"
#include "sim/sensors/ir_scanner_sensor.h"
#include "sim/world/occupancy_raster.h"

namespace plywood::eval {
namespace {

using Json = nlohmann::ordered_json;

double SegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                       const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-18), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

// Final and mean heading (deg) and position (m) errors of `estimate` against `truth`.
void AddPoseErrors(const std::vector<msgs::Pose2D>& truth,
                   const std::vector<msgs::Pose2D>& estimate, const std::string& key,
                   sim::Metrics& m) {
  double heading_sum = 0.0, position_sum = 0.0, heading = 0.0, position = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    heading = std::abs(msgs::WrapAngle(estimate[i].theta_rad - truth[i].theta_rad)) * kRadToDeg;
    position = std::hypot(estimate[i].x_m - truth[i].x_m, estimate[i].y_m - truth[i].y_m);
    heading_sum += heading;
    position_sum += position;
  }
  const double n = std::max<double>(1.0, static_cast<double>(truth.size()));
  m.Set(key + "final_heading_error_deg", heading);
  m.Set(key + "final_position_error_m", position);
  m.Set(key + "mean_heading_error_deg", heading_sum / n);
  m.Set(key + "mean_position_error_m", position_sum / n);
}

// Centre and radius of each small object of the world (cylinders up to 0.3 m radius, boxes whose
// faces are all at most 0.7 m), by geom id.
std::vector<std::pair<int, std::pair<Eigen::Vector2d, double>>> SmallObjects(
    const sim::GroundTruthWalls& walls) {
  std::vector<std::pair<int, std::pair<Eigen::Vector2d, double>>> objects;
  for (const auto& c : walls.circles) {
    if (c.radius_m <= 0.3) objects.push_back({c.geom_id, {c.centre, c.radius_m}});
  }
  std::map<int, std::vector<const sim::WallSegment*>> faces;
  for (const auto& s : walls.segments) faces[s.geom_id].push_back(&s);
  for (const auto& [geom, list] : faces) {
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    double longest = 0.0;
    for (const auto* s : list) {
      centre += s->a / static_cast<double>(list.size());
      longest = std::max(longest, s->LengthM());
    }
    if (longest <= 0.7) objects.push_back({geom, {centre, (list[0]->a - centre).norm()}});
  }
  return objects;
}

}  // namespace

const msgs::RangeRing* NearestSonarRing(const std::vector<msgs::RangeRing>& rings, double time_s,
                                        double max_age_s, std::size_t* cursor) {
  std::size_t& i = *cursor;
  while (i + 1 < rings.size() &&
         std::abs(rings[i + 1].time_s - time_s) <= std::abs(rings[i].time_s - time_s)) {
    ++i;
  }
  // A nanosecond of slack: the clock is a running sum of steps, and a ring max_age_s away by the
  // schedule (as the experiment's check counts it) may read 1e-16 s further.
  return i < rings.size() && std::abs(rings[i].time_s - time_s) <= max_age_s + 1e-9 ? &rings[i]
                                                                                    : nullptr;
}

GeometricMapRun BuildGeometricMap(const sim::RunRecord& record,
                                  const sim::GeometricMapConfig& config) {
  perception::GeometricMapper mapper(config.options);
  GeometricMapRun run;
  std::size_t next_sonar = 0;
  for (const sim::LaserRecord& ir : record.ir_scanner) {
    const msgs::RangeRing* sonar =
        NearestSonarRing(record.sonar, ir.scan.time_s, config.max_sonar_age_s, &next_sonar);
    run.corrected.push_back(mapper.AddScan(ir.scan, sonar, ir.X_WR_odometry));
    run.truth.push_back(ir.X_WR_truth);
    run.odometry.push_back(ir.X_WR_odometry);
  }
  run.map = mapper.map();
  run.scans = static_cast<long>(record.ir_scanner.size());
  run.points_seen = mapper.points_seen();
  run.sonar_points = mapper.sonar_points();
  return run;
}

bool AddGeometricMapMetrics(sim::ExperimentRunner& runner, GeometricMapRun* run) {
  const sim::GeometricMapConfig& config = runner.config().geometric_map;
  if (!config.given) return false;
  sim::RunRecord& record = runner.mutable_record();
  *run = BuildGeometricMap(record, config);
  const sim::GroundTruthWalls& walls = record.walls;

  // Wall surfaces the IR scanner observed. Hit by min_observed_rays beams in one scan is the
  // line-extraction issue's rule; the map, by its own definition, can only show a surface hit by
  // min_line_points beams (a line of one scan) in min_observations scans (a confirmed segment):
  // recall counts those, recall_single_scan the former.
  const int line_rays =
      std::max(config.scoring.min_observed_rays, config.options.segmentation.min_line_points);
  run->faces = JoinCollinearFaces(walls.segments, config.options.segmentation.dist_max_m);
  std::vector<int> face_of(walls.segments.size());
  std::vector<int> line_scans(run->faces.size(), 0);  // scans with line_rays beams on the face
  std::vector<perception::TruthSegment> truth(run->faces.size());
  for (std::size_t f = 0; f < run->faces.size(); ++f) {
    truth[f].a = run->faces[f].a;
    truth[f].b = run->faces[f].b;
    for (int k : run->faces[f].members) face_of[k] = static_cast<int>(f);
  }
  std::map<int, int> geom_hits;  // most beams on each geom in one scan
  for (const sim::LaserRecord& ir : record.ir_scanner) {
    std::map<int, int> face_count, geom_count;
    for (std::size_t i = 0; i < ir.hit_segment_ids.size(); ++i) {
      if (ir.hit_segment_ids[i] >= 0) ++face_count[face_of[ir.hit_segment_ids[i]]];
      if (ir.hit_geom_ids[i] >= 0) ++geom_count[ir.hit_geom_ids[i]];
    }
    for (const auto& [f, n] : face_count) {
      truth[f].observed_rays = std::max(truth[f].observed_rays, n);
      line_scans[f] += n >= line_rays;
    }
    for (const auto& [g, n] : geom_count) geom_hits[g] = std::max(geom_hits[g], n);
  }
  std::vector<perception::LineSegment> real;  // confirmed real segments: what the map claims
  long pseudo = 0, unconfirmed = 0;
  for (const auto& s : run->map.segments()) {
    if (s.pseudo) {
      ++pseudo;
    } else if (run->map.Confirmed(s)) {
      real.push_back(s.line);
    } else {
      ++unconfirmed;
    }
  }
  const std::vector<char> invisible = sim::IrInvisibleGeoms(runner.scene().model());
  std::map<int, bool> invisible_mapped;
  for (const auto& s : walls.segments) {
    if (s.geom_id >= 0 && invisible[s.geom_id]) invisible_mapped[s.geom_id] = false;
  }
  // The line-matching rule of line_scoring.h, applied in a frame centred on each map segment's
  // midpoint: the rule compares normal forms, whose r in the world frame would turn a 0.1 deg
  // tilt into centimetres 7 m from the origin. A surface is seen only from its outside, and the
  // two faces of an 18 mm partition lie within the rule's 5 cm of each other: only surfaces
  // facing the segment's observer (on its left) are candidates.
  std::vector<char> face_matched(truth.size(), 0);
  long matched_segments = 0;
  double endpoint_error = 0.0, sum_d_alpha_sq = 0.0;
  for (const auto& segment : real) {
    const Eigen::Vector2d centre = 0.5 * (segment.start + segment.end);
    const Eigen::Vector2d d = segment.end - segment.start;
    const Eigen::Vector2d observer_side(-d.y(), d.x());
    perception::LineSegment local = segment;
    local.start -= centre;
    local.end -= centre;
    perception::CanonicalNormalForm(std::atan2(-d.x(), d.y()), 0.0, &local.alpha_rad, &local.r_m);
    std::vector<perception::TruthSegment> facing;
    std::vector<int> facing_index;
    for (std::size_t k = 0; k < truth.size(); ++k) {
      const Eigen::Vector2d f = truth[k].b - truth[k].a;
      if (Eigen::Vector2d(f.y(), -f.x()).dot(observer_side) <= 0.0) continue;
      perception::TruthSegment t = truth[k];
      t.a -= centre;
      t.b -= centre;
      facing.push_back(t);
      facing_index.push_back(static_cast<int>(k));
    }
    double d_alpha = 0.0;
    const int match = perception::MatchSegment(local, facing, config.scoring, &d_alpha);
    if (match < 0) continue;
    const int k = facing_index[match];
    ++matched_segments;
    face_matched[k] = 1;
    sum_d_alpha_sq += d_alpha * d_alpha;
    endpoint_error += SegmentDistance(segment.start, truth[k].a, truth[k].b) +
                      SegmentDistance(segment.end, truth[k].a, truth[k].b);
    // An IR-invisible geom is mapped when the segment covers its own face by more than DIST_MAX
    // (the gap the joined surface bridges): the surface joins it to collinear visible faces, and
    // a segment along those alone, which the IR-only map gives, would otherwise count it.
    for (int member : run->faces[k].members) {
      const int geom = walls.segments[member].geom_id;
      if (invisible_mapped.count(geom) &&
          CoveredLengthM(walls.segments[member], segment.start, segment.end) >
              config.options.segmentation.dist_max_m) {
        invisible_mapped[geom] = true;
      }
    }
  }
  long observable = 0, observable_matched = 0, glimpsed = 0, glimpsed_matched = 0;
  run->face_observed_rays.clear();
  for (std::size_t k = 0; k < truth.size(); ++k) {
    run->face_observed_rays.push_back(truth[k].observed_rays);
    if (truth[k].observed_rays < config.scoring.min_observed_rays) continue;
    ++glimpsed;
    glimpsed_matched += face_matched[k];
    if (line_scans[k] < config.options.aggregation.min_observations) continue;
    ++observable;
    observable_matched += face_matched[k];
  }
  // No surface to find: recall (and the map's precision beside it) would read 1 for an empty map,
  // as the line scorer's did (docs/errors.md, "Scorers with empty ground truth").
  if (observable == 0) {
    const std::string scans = std::to_string(run->scans) + " IR scans";
    throw sim::ConfigError(
        runner.config().source_file, "geometric_map",
        glimpsed == 0
            ? "no wall surface was observable in any of the " + scans +
                  " (scoring.min_observed_rays = " +
                  std::to_string(config.scoring.min_observed_rays) +
                  " beams on it in one scan, within sensors.ir_scanner.range_max_m = " +
                  sim::FormatNumber(runner.config().sensors.ir_scanner->range_max_m) +
                  " m): recall is undefined, nothing to score against"
            : "no wall surface was hit by " + std::to_string(line_rays) +
                  " beams in aggregation.min_observations = " +
                  std::to_string(config.options.aggregation.min_observations) + " of the " + scans +
                  " (the most: " +
                  std::to_string(*std::max_element(line_scans.begin(), line_scans.end())) +
                  "): the map can confirm no segment, its recall is undefined, nothing to score "
                  "against");
  }
  run->face_line_scans = line_scans;
  run->face_matched = face_matched;
  long panels_mapped = 0;
  for (const auto& [geom, mapped] : invisible_mapped) panels_mapped += mapped;

  // Small objects the IR saw with enough beams to make a cluster, and those a cluster covers.
  long objects_seen = 0, objects_found = 0;
  const int min_points = config.options.segmentation.min_cluster_points;
  for (const auto& [geom, shape] : SmallObjects(walls)) {
    const auto hits = geom_hits.find(geom);
    if (hits == geom_hits.end() || hits->second < min_points) continue;
    ++objects_seen;
    for (const auto& c : run->map.clusters()) {
      if (c.box.exteriorDistance(shape.first) <= shape.second + 0.1) {
        ++objects_found;
        break;
      }
    }
  }

  sim::Metrics& m = record.metrics;
  const std::string key = "geometric_map.";
  m.Set(key + "scans", static_cast<double>(run->scans));
  m.Set(key + "points_seen", static_cast<double>(run->points_seen));
  m.Set(key + "sonar_points", static_cast<double>(run->sonar_points));
  m.Set(key + "segments", static_cast<double>(real.size()));
  m.Set(key + "pseudo_segments", static_cast<double>(pseudo));
  m.Set(key + "unconfirmed_segments", static_cast<double>(unconfirmed));
  // Figures of nothing are null, never 0 or 1 (s63): no segment, no segment matched, no small
  // object in view.
  const double kNull = std::numeric_limits<double>::quiet_NaN();
  m.Set(key + "points_per_segment",
        real.empty() ? kNull : static_cast<double>(run->points_seen) / real.size());
  m.Set(key + "clusters", static_cast<double>(run->map.clusters().size()));
  m.Set(key + "observed_walls", static_cast<double>(observable));
  m.Set(key + "recall", observable ? static_cast<double>(observable_matched) / observable : 1.0);
  m.Set(key + "glimpsed_walls", static_cast<double>(glimpsed));
  m.Set(key + "recall_single_scan",
        glimpsed ? static_cast<double>(glimpsed_matched) / glimpsed : 1.0);
  m.Set(key + "precision",
        real.empty() ? 1.0 : static_cast<double>(matched_segments) / real.size());
  m.Set(key + "orientation_error_deg",
        matched_segments ? std::sqrt(sum_d_alpha_sq / matched_segments) * kRadToDeg : kNull);
  m.Set(key + "endpoint_error_m",
        matched_segments ? endpoint_error / (2 * matched_segments) : kNull);
  m.Set(key + "small_objects_observed", static_cast<double>(objects_seen));
  m.Set(key + "cluster_recall",
        objects_seen ? static_cast<double>(objects_found) / objects_seen : kNull);
  m.Set(key + "ir_invisible_geoms", static_cast<double>(invisible_mapped.size()));
  m.Set(key + "ir_invisible_mapped", static_cast<double>(panels_mapped));
  AddPoseErrors(run->truth, run->corrected, key + "pose.corrected.", m);
  AddPoseErrors(run->truth, run->odometry, key + "pose.odometry.", m);
  return true;
}

void WriteGeometricMapJson(const GeometricMapRun& run, const std::string& out_dir) {
  const auto point = [](const Eigen::Vector2d& p) { return Json::array({p.x(), p.y()}); };
  Json json = Json::object();
  Json segments = Json::array();
  for (const auto& s : run.map.segments()) {
    Json segment = {{"start", point(s.line.start)},
                    {"end", point(s.line.end)},
                    {"tag", s.pseudo               ? "pseudo"
                            : run.map.Confirmed(s) ? "real"
                                                   : "unconfirmed"},
                    {"points", s.line.num_points},
                    {"inliers", s.inliers},
                    {"observations", s.observations}};
    // Why a segment seen often enough is not real: its scans' pieces bend like a small object.
    if (std::isfinite(s.curvature.sigma_per_m)) {
      segment["curvature_per_m"] = s.curvature.curvature_per_m;
      segment["curvature_sigma_per_m"] = s.curvature.sigma_per_m;
    }
    segments.push_back(segment);
  }
  Json clusters = Json::array();
  for (const auto& c : run.map.clusters()) {
    clusters.push_back(
        {{"min", point(c.box.min())}, {"max", point(c.box.max())}, {"points", c.points}});
  }
  Json poses = Json::array();
  for (const auto& p : run.corrected) poses.push_back(Json::array({p.x_m, p.y_m, p.theta_rad}));
  // The wall surfaces the IR scanner hit (joined faces, walls.csv's segments), matched or not.
  Json faces = Json::array();
  for (std::size_t k = 0; k < run.face_observed_rays.size(); ++k) {
    if (run.face_observed_rays[k] == 0) continue;
    faces.push_back({{"a", point(run.faces[k].a)},
                     {"b", point(run.faces[k].b)},
                     {"walls_csv_segments", run.faces[k].members},
                     {"observed_rays", run.face_observed_rays[k]},
                     {"line_scans", run.face_line_scans[k]},
                     {"matched", run.face_matched[k] != 0}});
  }
  json["segments"] = segments;
  json["faces"] = faces;
  json["clusters"] = clusters;
  json["corrected_poses"] = poses;
  std::filesystem::create_directories(out_dir);
  sim::WriteTextFile(std::filesystem::path(out_dir) / "geometric_map.json", sim::WriteJson(json));
}

void WriteGeometricMapPicture(const sim::ExperimentRunner& runner, const GeometricMapRun& run,
                              const std::string& out_dir) {
  const sim::RunRecord& record = runner.record();
  const mjModel* model = runner.scene().model();
  sim::OccupancyRasterOptions raster_options;
  raster_options.resolution_m = sim::kGeometricMapPictureResolutionM;
  const int site = mj_name2id(model, mjOBJ_SITE, "ir_scanner");
  if (site >= 0) raster_options.height_m = runner.scene().data()->site_xpos[3 * site + 2];
  const sim::OccupancyRaster raster = sim::RasteriseOccupancy(model, raster_options);
  render::WorldBounds bounds = render::WorldBounds::Empty();
  bounds.Extend(raster.origin_xy);
  bounds.Extend(raster.origin_xy +
                raster.resolution_m * Eigen::Vector2d(raster.width, raster.height));
  const render::TopDownFrame frame = render::FrameBounds(bounds.Padded(0.2), 1600);
  const render::WorldToPixel& map = frame.world_to_pixel;
  render::RgbImage image(frame.width_px, frame.height_px);
  render::Fill(image, render::colours::kWhite);
  for (int y = 0; y < frame.height_px; ++y) {
    for (int x = 0; x < frame.width_px; ++x) {
      const auto cell = raster.CellAt(map.ToWorld({x + 0.5, y + 0.5}));
      if (cell && raster.IsOccupied(cell->x(), cell->y())) {
        render::BlendPixel(image, x, y, {200, 200, 200});
      }
    }
  }
  const std::vector<char> invisible = sim::IrInvisibleGeoms(model);
  for (const auto& s : record.walls.segments) {
    if (s.geom_id >= 0 && invisible[s.geom_id]) {
      render::DrawSegment(image, map, s.a, s.b, {120, 190, 240}, 4.0);
    }
  }
  std::vector<Eigen::Vector2d> path;
  for (const auto& p : run.truth) path.emplace_back(p.x_m, p.y_m);
  render::DrawPolyline(image, map, path, {90, 90, 90}, 1.0);
  for (const auto& s : run.map.segments()) {
    if (run.map.Confirmed(s)) {
      render::DrawSegment(image, map, s.line.start, s.line.end, render::colours::kRed, 2.5);
      continue;
    }
    if (!s.pseudo) continue;  // unconfirmed: in the JSON only
    // Dashes of 10 cm every 20 cm.
    const Eigen::Vector2d d = s.line.end - s.line.start;
    const double length = d.norm();
    for (double t = 0.0; t < length; t += 0.2) {
      render::DrawSegment(image, map, s.line.start + d * (t / length),
                          s.line.start + d * (std::min(t + 0.1, length) / length),
                          render::colours::kOrange, 1.5);
    }
  }
  for (const auto& c : run.map.clusters()) {
    const Eigen::Vector2d a = c.box.min(), b = c.box.max();
    const std::vector<Eigen::Vector2d> box = {a, {b.x(), a.y()}, b, {a.x(), b.y()}, a};
    render::DrawPolyline(image, map, box, render::colours::kGreen, 2.0);
  }
  std::filesystem::create_directories(out_dir);
  render::WritePng(image, std::filesystem::path(out_dir) / "geometric_map.png");
}

}  // namespace plywood::eval
