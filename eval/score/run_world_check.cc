#include "eval/score/run_world_check.h"

#include <algorithm>
#include <optional>
#include <string>

#include "msgs/shortest_number.h"
#include "sim/config/config_error.h"

namespace plywood::eval {
namespace {

std::string Describe(const sim::WallSegment& s) {
  return "geom " + std::to_string(s.geom_id) + " face " + std::to_string(s.face_index) + " (" +
         msgs::ShortestNumber(s.a.x()) + ", " + msgs::ShortestNumber(s.a.y()) + ") - (" +
         msgs::ShortestNumber(s.b.x()) + ", " + msgs::ShortestNumber(s.b.y()) + ")";
}

bool Same(const sim::WallSegment& a, const sim::WallSegment& b) {
  return a.geom_id == b.geom_id && a.face_index == b.face_index && a.a == b.a && a.b == b.b;
}

}  // namespace

void RequireWorldAsTheRunSawIt(const sim::Scene& scene, const sim::ExperimentConfig& config,
                               const sim::GroundTruthWalls& run_walls,
                               const std::filesystem::path& config_yaml,
                               const std::string& consequence) {
  // The height the run cut the world at (sim::ExperimentRunner): its laser's, else its IR
  // scanner's, else every height.
  sim::GroundTruthOptions options;
  std::optional<int> site;
  if (config.sensors.laser) {
    site = scene.FindSite("laser");
  } else if (config.sensors.ir_scanner) {
    site = scene.FindSite("ir_scanner");
  }
  if (site) options.height_m = scene.SitePoseInWorld(*site).translation().z();
  const sim::GroundTruthWalls now = sim::ExtractGroundTruthWalls(scene.model(), options);
  const auto changed = [&](const std::string& how) {
    throw sim::ConfigError(
        config_yaml.string(), "world",
        config.world_path.string() + " changed since the run (" + how + "); " + consequence);
  };
  const std::size_t n = std::min(now.segments.size(), run_walls.segments.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (!Same(now.segments[i], run_walls.segments[i])) {
      changed("walls.csv segment " + std::to_string(i) + " is " + Describe(run_walls.segments[i]) +
              ", the world now gives " + Describe(now.segments[i]));
    }
  }
  if (now.segments.size() != run_walls.segments.size()) {
    changed("walls.csv holds " + std::to_string(run_walls.segments.size()) +
            " wall faces, the world now gives " + std::to_string(now.segments.size()));
  }
}

}  // namespace plywood::eval
