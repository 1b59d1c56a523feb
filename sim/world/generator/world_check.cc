#include "sim/world/generator/world_check.h"

#include <array>
#include <cmath>
#include <numbers>

#include "sim/runner/out_of_memory.h"
#include "sim/world/ground_truth_walls.h"
#include "sim/world/mujoco_handles.h"
#include "sim/world/scene.h"
#include "sim/world/world_spawns.h"

namespace plywood::sim::worldgen {
namespace {

// The MJCF carries 6 decimals: centres and sizes to 0.5 um, so corners agree to a few um.
constexpr double kTolerance = 5e-6;

bool Near(double a, double b) { return std::abs(a - b) <= kTolerance; }

// Does the compiled upright geom describe the generated one?
std::string Mismatch(const UprightGeom& u, const WorldGeom& g) {
  if ((u.shape == UprightGeom::Shape::kCylinder) != (g.shape == WorldGeom::Shape::kCylinder)) {
    return "shape";
  }
  if ((u.centre_W - g.centre).norm() > kTolerance) return "centre";
  if (!Near(u.z_min_m, g.z_min_m) || !Near(u.z_max_m, g.z_max_m)) return "height";
  if (g.shape == WorldGeom::Shape::kCylinder) return Near(u.radius_m, g.radius_m) ? "" : "radius";
  if ((u.half_size_xy - g.half_size).norm() > kTolerance) return "size";
  const double yaw = g.yaw_deg * std::numbers::pi / 180.0;
  if (!Near(u.R_WG(0, 0), std::cos(yaw)) || !Near(u.R_WG(1, 0), std::sin(yaw))) return "yaw";
  return "";
}

}  // namespace

std::vector<std::string> CheckWrittenWorld(const std::filesystem::path& mjcf,
                                           const GeneratedWorld& world,
                                           const RobotCatalogEntry& robot) {
  std::vector<std::string> defects;
  const std::string name = mjcf.filename().string();
  MjModelPtr model;
  const std::string warning_before = LastMujocoWarning();
  try {
    model = LoadModelFromFile(mjcf.string());
  } catch (const OutOfMemory&) {
    throw;  // not the file's fault: said as such
  } catch (const std::exception& e) {
    return {name + ": does not compile: " + e.what()};
  }
  if (LastMujocoWarning() != warning_before) {
    defects.push_back(name + ": MuJoCo warning: " + LastMujocoWarning());
  }
  const mjModel* m = model.get();
  if (m->ngeom != static_cast<int>(world.geoms.size()) + 1) {
    defects.push_back(name + ": " + std::to_string(m->ngeom) + " geoms, generated " +
                      std::to_string(world.geoms.size()) + " and the floor");
    return defects;
  }
  const std::vector<UprightGeom> upright = ExtractUprightGeoms(m);
  if (upright.size() != world.geoms.size()) {
    defects.push_back(name + ": " + std::to_string(upright.size()) + " upright geoms, generated " +
                      std::to_string(world.geoms.size()));
    return defects;
  }
  for (size_t i = 0; i < upright.size(); ++i) {
    const WorldGeom& g = world.geoms[i];
    const char* compiled_name = mj_id2name(m, mjOBJ_GEOM, upright[i].geom_id);
    if (compiled_name == nullptr || g.name != compiled_name) {
      defects.push_back(name + ": geom " + std::to_string(i) + " is not " + g.name);
    } else if (const std::string what = Mismatch(upright[i], g); !what.empty()) {
      defects.push_back(name + ": " + g.name + ": " + what + " differs from the generated one");
    }
  }
  for (size_t k = 0; k < world.spawns.size(); ++k) {
    const std::string spawn = "spawn_" + std::to_string(k);
    const std::optional<std::array<double, 3>> read = WorldSpawn(m, static_cast<int>(k));
    const SpawnPose& p = world.spawns[k];
    if (!read) {
      defects.push_back(name + ": " + spawn + " missing");
      continue;
    }
    const std::array<double, 3>& v = *read;
    if (!Near(v[0], p.x_m) || !Near(v[1], p.y_m) || !Near(v[2], p.yaw_deg)) {
      defects.push_back(name + ": " + spawn + " reads back differently");
    }
    SceneOptions options;
    options.world_mjcf = mjcf;
    options.robot_mjcf = robot.mjcf;
    options.spawn = {p.x_m, p.y_m, p.yaw_deg * std::numbers::pi / 180.0};
    const Scene scene(options);
    const mjData* d = scene.data();
    for (int c = 0; c < d->ncon; ++c) {
      const int g1 = d->contact[c].geom1, g2 = d->contact[c].geom2;
      const int other = scene.IsRobotGeom(g1) ? g2 : g1;
      if (scene.model()->geom_type[other] != mjGEOM_PLANE) {
        const char* touched = mj_id2name(scene.model(), mjOBJ_GEOM, other);
        defects.push_back(name + ": " + robot.name + " at " + spawn + " touches " +
                          (touched ? touched : "an unnamed geom"));
      }
    }
  }
  return defects;
}

}  // namespace plywood::sim::worldgen
