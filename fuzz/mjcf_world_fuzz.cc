// MJCF worlds through the world loader (sim/world/scene.h) with the P3-DX, then the setup checks
// and the ground-truth walls a run computes before its first step: each loads or is refused with
// one line naming the world file.
#include "fuzz/fuzz_support.h"
#include "fuzz/fuzz_target.h"
#include "plywood_paths.h"
#include "sim/config/config_error.h"
#include "sim/world/ground_truth_walls.h"
#include "sim/world/scene.h"
#include "sim/world/setup_checks.h"

namespace plywood::fuzz {
namespace {

void FuzzMjcfWorld(std::span<const std::uint8_t> data) {
  const std::filesystem::path path = WriteScratchFile("world.xml", data);
  sim::SceneOptions options;
  options.world_mjcf = path;
  options.robot_mjcf = std::filesystem::path(PLYWOOD_SOURCE_ROOT) / "models" / "p3dx.xml";
  try {
    const sim::Scene scene(options);
    sim::MissingFloor(scene);
    sim::MovableWorldGeometry(scene);
    sim::SpawnCollision(scene);
    sim::SpawnOutsideWorld(scene);
    const sim::GroundTruthWalls walls = sim::ExtractGroundTruthWalls(scene.model());
    for (const sim::WallSegment& segment : walls.segments) {
      Require(segment.a.allFinite() && segment.b.allFinite(), "a non-finite wall");
    }
  } catch (const sim::ConfigError& e) {
    RequireCleanError(e, path.string());
  }
}

}  // namespace
}  // namespace plywood::fuzz

PLYWOOD_FUZZ_TARGET("mjcf_world", plywood::fuzz::FuzzMjcfWorld)
