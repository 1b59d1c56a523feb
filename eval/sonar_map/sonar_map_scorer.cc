#include "eval/sonar_map/sonar_map_scorer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

#include "eval/sonar_map/body_reach.h"
#include "eval/sonar_map/cognitive_map_json.h"
#include "eval/sonar_map/narrow_gaps.h"
#include "eval/sonar_map/sonar_ground_truth.h"
#include "msgs/shortest_number.h"
#include "perception/sonar_map/sonar_explorer.h"
#include "render/png_image.h"
#include "sim/config/config_error.h"
#include "sim/runner/format_number.h"
#include "sim/runner/text_file.h"
#include "sim/world/occupancy_raster.h"
#include "sim/world/planar_obstacles.h"

namespace plywood::eval {
namespace {

bool GridFree(const perception::LogOddsGrid& grid, const Eigen::Vector2d& p) {
  const Eigen::Vector2i c = grid.CellAt(p);
  return c.x() < 0 || grid.LogOdds(c.x(), c.y()) <= 0.0;
}

bool MapFree(const perception::CognitiveMap& map, const Eigen::Vector2d& p) {
  const int i = map.partitions.Find(p);
  return i >= 0 && map.partitions.partitions()[i].label == perception::Label::kFree;
}

void Line(render::RgbImage& image, Eigen::Vector2d a, Eigen::Vector2d b,
          const std::array<std::uint8_t, 3>& colour) {
  const int steps = static_cast<int>(std::ceil((b - a).norm())) + 1;
  for (int k = 0; k <= steps; ++k) {
    const Eigen::Vector2d p = a + (b - a) * (static_cast<double>(k) / steps);
    const int x = static_cast<int>(std::lround(p.x())), y = static_cast<int>(std::lround(p.y()));
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (x + dx >= 0 && y + dy >= 0 && x + dx < image.width && y + dy < image.height)
          std::copy(colour.begin(), colour.end(), image.At(x + dx, y + dy));
  }
}

// The radius of the round body the body-reach truth moves: the reach of the robot's bumper ring
// about its base origin (the footprint the planar drive stops with). None without a ring.
std::optional<double> BodyRadius(const sim::Scene& scene, const std::string& source) {
  const mjModel* m = scene.model();
  const int ring = mj_name2id(m, mjOBJ_GEOM, "bumper_ring");
  if (ring < 0 || m->geom_type[ring] != mjGEOM_MESH) return std::nullopt;
  return sim::PlanarObstacles(m, scene.data(), scene.base_body_id(), source).reach_m();
}

}  // namespace

std::unique_ptr<OccupancyTruth> RequireASonarMapTruth(const sim::ExperimentRunner& runner) {
  if (dynamic_cast<const perception::SonarExplorer*>(runner.controller()) == nullptr) {
    return nullptr;
  }
  const sim::ExperimentConfig& config = runner.config();
  auto truth = MakeOccupancyTruth(runner.scene().model(), {config.spawn.x_m, config.spawn.y_m},
                                  config.source_file);
  if (const auto edge = truth->ReachableCellOnTheEdge()) {
    throw sim::ConfigError(
        config.source_file, "world",
        config.world_path.string() + ": the free space round the robot at (" +
            sim::FormatNumber(config.spawn.x_m) + ", " + sim::FormatNumber(config.spawn.y_m) +
            ") reaches (" + msgs::MillimetreNumber(edge->x()) + ", " +
            msgs::MillimetreNumber(edge->y()) +
            "), the edge of the world's walls: no wall closes the room there (one left out, or a "
            "gap), so the sonar map's truth would end where nothing in the world does and the "
            "explorer would drive out of the room; close the room");
  }
  // The explorer's grid spans the spawn +- grid_half_extent_m. A room reaching past it cannot be
  // held by the map, yet the tour ends map_complete (an office from its spawn: error 0.78, a
  // generated doorways room 1.07), and the error is of a map that never had the room's far part.
  const double half_extent_m = config.controller.sonar_explorer.grid_half_extent_m;
  const double res = truth->raster.resolution_m;
  const Eigen::Vector2d spawn(config.spawn.x_m, config.spawn.y_m);
  const Eigen::Vector2d low =
      truth->raster.origin_xy + Eigen::Vector2d(truth->x0, truth->y0) * res - spawn;
  const Eigen::Vector2d high =
      truth->raster.origin_xy + Eigen::Vector2d(truth->x1 + 1, truth->y1 + 1) * res - spawn;
  const double reach_m = std::max({-low.x(), -low.y(), high.x(), high.y()});
  if (reach_m > half_extent_m) {
    throw sim::ConfigError(
        config.source_file, "controller.grid_half_extent_m",
        "the free space round the robot at (" + sim::FormatNumber(config.spawn.x_m) + ", " +
            sim::FormatNumber(config.spawn.y_m) + ") spans x in [" +
            msgs::MillimetreNumber(spawn.x() + low.x()) + ", " +
            msgs::MillimetreNumber(spawn.x() + high.x()) + "], y in [" +
            msgs::MillimetreNumber(spawn.y() + low.y()) + ", " +
            msgs::MillimetreNumber(spawn.y() + high.y()) + "] in " +
            config.world_path.filename().string() + ", " + msgs::MillimetreNumber(reach_m) +
            " m from the spawn, beyond the explorer's grid (" + sim::FormatNumber(half_extent_m) +
            " m each way): the map cannot hold the room, so the tour would end map_complete on "
            "part of it and the occupancy error would score a map that never had the rest; give "
            "at least " +
            msgs::MillimetreNumber(std::ceil(reach_m * 10.0) / 10.0) + " (or move robot.spawn)");
  }
  return truth;
}

bool AddSonarMapMetrics(sim::ExperimentRunner& runner, const OccupancyTruth* truth) {
  const auto* explorer = dynamic_cast<const perception::SonarExplorer*>(runner.controller());
  if (explorer == nullptr) return false;
  const auto& spawn = runner.config().spawn;
  std::unique_ptr<OccupancyTruth> made;
  if (truth == nullptr) {
    made = MakeOccupancyTruth(runner.scene().model(), {spawn.x_m, spawn.y_m},
                              runner.config().source_file);
    truth = made.get();
  }
  const perception::CognitiveMap map = explorer->Map();
  const OccupancyError map_error =
      ScoreOccupancy(*truth, [&](const Eigen::Vector2d& p) { return MapFree(map, p); });
  const OccupancyError grid_error = ScoreOccupancy(
      *truth, [&](const Eigen::Vector2d& p) { return GridFree(explorer->grid(), p); });
  sim::Metrics& m = runner.mutable_record().metrics;
  m.Set("occupancy.error", map_error.Error());
  m.Set("occupancy.grid_error", grid_error.Error());
  m.Set("occupancy.area_total_m2", map_error.AreaTotalM2());
  m.Set("occupancy.area_error_m2", map_error.AreaErrorM2());
  // Beside e, not instead of it: the same map scored as if the space the robot's body cannot reach
  // from the spawn (behind gaps narrower than the body) were not free (issue 14, question 6).
  if (const auto radius = BodyRadius(runner.scene(), runner.config().source_file)) {
    const auto body = MakeBodyReachTruth(*truth, {spawn.x_m, spawn.y_m}, *radius);
    const OccupancyError body_error =
        ScoreOccupancy(*body, [&](const Eigen::Vector2d& p) { return MapFree(map, p); });
    m.Set("occupancy.error_body_reach", body_error.Error());
    m.Set("occupancy.area_body_reach_m2", body_error.AreaTotalM2());
    // Also beside e: the same map with the gaps narrower than the body left unscored, which the
    // seed's method keeps obstacle by its own rule and the world has free (question 6).
    const auto wide = MakeTruthWithoutNarrowGaps(*truth, 2.0 * *radius);
    const OccupancyError wide_error =
        ScoreOccupancy(*wide, [&](const Eigen::Vector2d& p) { return MapFree(map, p); });
    m.Set("occupancy.error_without_narrow_gaps", wide_error.Error());
    m.Set("occupancy.area_narrow_gaps_m2", map_error.AreaTotalM2() - wide_error.AreaTotalM2());
  }
  m.Set("occupancy.partitions", static_cast<double>(map.partitions.partitions().size()));
  m.Set("occupancy.graph_nodes", static_cast<double>(map.graph.nodes.size()));
  m.Set("occupancy.graph_edges", static_cast<double>(map.graph.arcs.size()));
  m.Set("occupancy.negative_experience", static_cast<double>(map.negative.size()));
  m.Set("occupancy.rings", static_cast<double>(explorer->rings_integrated()));
  m.Set("occupancy.explored", explorer->Finished() ? 1.0 : 0.0);
  // map_complete: nothing left to visit; time_limit: explore_max_s; run_ended: the experiment's
  // duration ran out first.
  m.Set("exploration.end_reason",
        explorer->Finished() ? explorer->end_reason() : std::string("run_ended"));
  // The controller's clock is MuJoCo's float sum of the steps: reported at the step's decimals.
  if (explorer->Finished()) {
    m.Set("exploration.end_time_s",
          sim::TimeAtStepPrecision(explorer->end_time_s(), runner.scene().timestep_s()));
  }
  // Obstacles gone round, and how many of those circuits heard all four sides.
  m.Set("exploration.obstacles_circled", static_cast<double>(explorer->circled_obstacles().size()));
  m.Set("exploration.circuits_closed", static_cast<double>(explorer->closed_outlines().size()));
  return true;
}

void WriteSonarMap(const sim::ExperimentRunner& runner, const std::string& out_dir) {
  const auto* explorer = dynamic_cast<const perception::SonarExplorer*>(runner.controller());
  if (explorer == nullptr) return;
  std::filesystem::create_directories(out_dir);
  const std::filesystem::path path = std::filesystem::path(out_dir) / "cognitive_map.json";
  sim::WriteTextFile(path, CognitiveMapToJson(explorer->Map()));
  // The explorer's decisions, so that a run's course (why it ended where it did) can be read
  // without a debugging build (perception/sonar_map/exploration_event.h); positions to 0.1 mm as
  // cognitive_map.json's.
  std::string log = "time_s,event,detail,x_m,y_m\n";
  for (const perception::ExplorationEvent& e : explorer->events()) {
    log += sim::FormatNumber(sim::TimeAtStepPrecision(e.time_s, runner.scene().timestep_s())) +
           "," + e.kind + "," + e.detail + "," + sim::FormatFixed(e.at.x(), 4) + "," +
           sim::FormatFixed(e.at.y(), 4) + "\n";
  }
  sim::WriteTextFile(std::filesystem::path(out_dir) / "exploration_log.csv", log);
}

void WriteSonarMapPictures(const sim::ExperimentRunner& runner, const std::string& out_dir) {
  const auto* explorer = dynamic_cast<const perception::SonarExplorer*>(runner.controller());
  if (explorer == nullptr) return;
  const auto& spawn = runner.config().spawn;
  const auto truth = MakeOccupancyTruth(runner.scene().model(), {spawn.x_m, spawn.y_m},
                                        runner.config().source_file);
  const perception::CognitiveMap map = explorer->Map();
  // 1 px per cm, the room's box plus 0.3 m on every side.
  const int margin = 30;
  const int x0 = std::max(0, truth->x0 - margin), y0 = std::max(0, truth->y0 - margin);
  const int x1 = std::min(truth->raster.width - 1, truth->x1 + margin);
  const int y1 = std::min(truth->raster.height - 1, truth->y1 + margin);
  render::RgbImage grid_image(x1 - x0 + 1, y1 - y0 + 1), part_image(x1 - x0 + 1, y1 - y0 + 1);
  auto pixel = [&](int ix, int iy) { return Eigen::Vector2i(ix - x0, y1 - iy); };
  for (int iy = y0; iy <= y1; ++iy)
    for (int ix = x0; ix <= x1; ++ix) {
      const Eigen::Vector2d p = truth->raster.CellCentre(ix, iy);
      // The true geometry is drawn as its outline, so that what the map says inside an obstacle
      // (and the wall band) stays visible.
      auto solid = [&](int jx, int jy) {
        return jx < 0 || jy < 0 || jx >= truth->raster.width || jy >= truth->raster.height ||
               truth->raster.IsOccupied(jx, jy);
      };
      const bool occupied =
          truth->raster.IsOccupied(ix, iy) &&
          !(solid(ix - 1, iy) && solid(ix + 1, iy) && solid(ix, iy - 1) && solid(ix, iy + 1) &&
            solid(ix - 2, iy) && solid(ix + 2, iy) && solid(ix, iy - 2) && solid(ix, iy + 2));
      const Eigen::Vector2i px = pixel(ix, iy);
      const Eigen::Vector2i c = explorer->grid().CellAt(p);
      const double prob = c.x() < 0 ? 0.5 : explorer->grid().Probability(c.x(), c.y());
      const auto g = static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - prob)));
      std::uint8_t* q = grid_image.At(px.x(), px.y());
      q[0] = occupied ? 220 : g;
      q[1] = occupied ? 30 : g;
      q[2] = occupied ? 30 : g;
      std::uint8_t* r = part_image.At(px.x(), px.y());
      const int i = map.partitions.Find(p);
      if (occupied) {
        r[0] = 220, r[1] = 30, r[2] = 30;
      } else if (i < 0) {
        r[0] = r[1] = r[2] = 90;
      } else if (map.partitions.partitions()[i].label == perception::Label::kFree) {
        r[0] = 200, r[1] = 235, r[2] = 200;
      } else {
        r[0] = r[1] = r[2] = 60;
      }
    }
  auto to_px = [&](const Eigen::Vector2d& p) {
    const Eigen::Vector2d q = (p - truth->raster.origin_xy) / truth->raster.resolution_m;
    return Eigen::Vector2d(q.x() - x0, y1 - q.y());
  };
  for (const auto& part : map.partitions.partitions()) {
    const auto& rc = part.rect;
    const Eigen::Vector2d a = to_px({rc.x0, rc.y0}), b = to_px({rc.x1, rc.y0}),
                          c = to_px({rc.x1, rc.y1}), d = to_px({rc.x0, rc.y1});
    const std::array<std::uint8_t, 3> black{0, 0, 0};
    Line(part_image, a, b, black);
    Line(part_image, b, c, black);
    Line(part_image, c, d, black);
    Line(part_image, d, a, black);
  }
  const auto& parts = map.partitions.partitions();
  for (const auto& arc : map.graph.arcs) {
    const Eigen::Vector2d door = 0.5 * (arc.door_a + arc.door_b);
    const std::array<std::uint8_t, 3> blue{30, 60, 220};
    Line(part_image, to_px(parts[arc.a].rect.Centre()), to_px(door), blue);
    Line(part_image, to_px(door), to_px(parts[arc.b].rect.Centre()), blue);
  }
  std::filesystem::create_directories(out_dir);
  render::WritePng(grid_image, std::filesystem::path(out_dir) / "occupancy_grid.png");
  render::WritePng(part_image, std::filesystem::path(out_dir) / "occupancy_partitions.png");
}

}  // namespace plywood::eval
