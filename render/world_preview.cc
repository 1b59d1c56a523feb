#include "render/world_preview.h"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "render/overlay.h"
#include "render/snapshot.h"
#include "sim/world/ground_truth_walls.h"
#include "sim/world/mujoco_handles.h"
#include "sim/world/world_spawns.h"

namespace plywood::render {

void WriteWorldPreview(const std::filesystem::path& world_mjcf, double robot_reach_m,
                       const std::filesystem::path& png, int longer_side_px) {
  const sim::MjModelPtr model = sim::LoadModelFromFile(world_mjcf.string());
  const sim::MjDataPtr data(mj_makeData(model.get()));
  mj_forward(model.get(), data.get());
  SnapshotOptions options;
  options.view.longer_side_px = longer_side_px;
  options.legend = false;
  Snapshot snapshot = RenderSnapshot(model.get(), data.get(), {}, options);
  const mjModel* m = model.get();
  const WorldToPixel& map = snapshot.picture.world_to_pixel;
  // 18 mm walls are under a pixel wide in a large world: trace their faces.
  for (const sim::WallSegment& s : sim::ExtractGroundTruthWalls(m).segments) {
    const char* name = mj_id2name(m, mjOBJ_GEOM, s.geom_id);
    if (name != nullptr && std::string(name).rfind("wall_", 0) == 0) {
      DrawSegment(snapshot.picture.image, map, s.a, s.b, Rgb{110, 75, 40}, 2.0);
    }
  }
  for (int k = 0;; ++k) {
    const std::optional<std::array<double, 3>> spawn = sim::WorldSpawn(m, k);
    if (!spawn) break;
    const std::array<double, 3>& v = *spawn;
    const Eigen::Vector2d p(v[0], v[1]);
    const Rgb colour = k == 0 ? colours::kRed : colours::kBlue;
    DrawCircle(snapshot.picture.image, map, p, robot_reach_m, colour, 2.0);
    DrawPoseMarker(snapshot.picture.image, map, p, v[2] * std::numbers::pi / 180.0, colour, 14.0);
  }
  WritePng(snapshot.picture.image, png);
}

}  // namespace plywood::render
