// Validity of every generator family over 20 worlds each (seed 1): the MJCF compiles without
// warnings and follows worlds/README.md; the ground truth read from it has exactly the generated
// boxes' faces and cylinders; nothing but walls overlaps; every spawn pose is free for the largest
// robot, inside the room (a flood fill from spawn_0 reaches every spawn and, in a closed world,
// never the outside) and the laser at spawn_0 sees something within 4 m; both robots placed at the
// spawn poses touch only the floor and stay put; and the sidecar's parameters lie in the ranges of
// docs/worlds.md. PLYWOOD_WORLDS_SEED and PLYWOOD_WORLDS_COUNT check other seeds and more worlds
// (scripts/check_generated_worlds: worlds nobody has looked at).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <queue>
#include <set>

#include "sim/world/generator/robot_reach.h"
#include "sim/world/generator/spawn_placer.h"
#include "sim/world/generator/world_families.h"
#include "sim/world/generator/world_generator.h"
#include "sim/world/ground_truth_walls.h"
#include "sim/world/mujoco_handles.h"
#include "sim/world/occupancy_raster.h"
#include "sim/world/scene.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::sim::worldgen {
namespace {

namespace fs = std::filesystem;
using Eigen::Vector2d;

// The environment's value of `name` (a whole number >= `min`), else `fallback`.
int EnvironmentInt(const char* name, int fallback, int min) {
  const char* text = std::getenv(name);
  if (text == nullptr || *text == '\0') return fallback;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (*end != '\0' || value < min || value > 1000000) {
    ADD_FAILURE() << name << "=" << text << ": not a whole number in [" << min << ", 1e6]";
    return fallback;
  }
  return static_cast<int>(value);
}
constexpr double kPi = std::numbers::pi;

struct Loaded {
  MjModelPtr model;
  YAML::Node sidecar;
  GeneratedWorld world;
};

std::vector<msgs::Pose2D> SpawnPoses(const mjModel* m) {
  std::vector<msgs::Pose2D> spawns;
  for (int i = 0;; ++i) {
    const int id = mj_name2id(m, mjOBJ_NUMERIC, ("spawn_" + std::to_string(i)).c_str());
    if (id < 0) break;
    EXPECT_EQ(m->numeric_size[id], 3);
    const mjtNum* v = m->numeric_data + m->numeric_adr[id];
    spawns.push_back({v[0], v[1], v[2] * kPi / 180.0});
  }
  return spawns;
}

bool StartsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// The compiled model holds the floor and exactly the generated geoms, walls 18 mm x 1 m, and the
// ground truth's faces are the generated boxes' faces.
void ExpectGeometryMatches(const mjModel* m, const GeneratedWorld& world) {
  ASSERT_EQ(m->ngeom, static_cast<int>(world.geoms.size()) + 1);
  const int floor = mj_name2id(m, mjOBJ_GEOM, "floor");
  ASSERT_GE(floor, 0);
  EXPECT_EQ(m->geom_type[floor], mjGEOM_PLANE);
  EXPECT_EQ(m->nbody, 1);
  EXPECT_EQ(m->njnt, 0);
  const GroundTruthWalls truth = ExtractGroundTruthWalls(m);
  EXPECT_TRUE(truth.unrepresented_geom_ids.empty());
  size_t segment = 0, circle = 0;
  for (const WorldGeom& g : world.geoms) {
    const int id = mj_name2id(m, mjOBJ_GEOM, g.name.c_str());
    ASSERT_GE(id, 0) << g.name;
    EXPECT_NE(m->geom_group[id], Scene::kRobotGeomGroup);
    if (StartsWith(g.name, "wall_")) {
      EXPECT_EQ(g.shape, WorldGeom::Shape::kBox);
      EXPECT_NEAR(m->geom_size[3 * id + 1], 0.009, 1e-12) << g.name;
      EXPECT_NEAR(m->geom_pos[3 * id + 2] + m->geom_size[3 * id + 2], 1.0, 1e-12) << g.name;
    }
    if (g.shape == WorldGeom::Shape::kCylinder) {
      ASSERT_LT(circle, truth.circles.size());
      const WallCircle& c = truth.circles[circle++];
      EXPECT_EQ(c.geom_id, id);
      EXPECT_NEAR((c.centre - g.centre).norm(), 0.0, 5e-6) << g.name;
      EXPECT_NEAR(c.radius_m, g.radius_m, 1e-6) << g.name;
      continue;
    }
    // Faces +x, +y, -x, -y of the generated box, each running counter-clockwise.
    const double yaw = g.yaw_deg * kPi / 180.0;
    const Vector2d ux(std::cos(yaw), std::sin(yaw)), uy(-ux.y(), ux.x());
    const Vector2d hx = g.half_size.x() * ux, hy = g.half_size.y() * uy;
    const Vector2d corners[4] = {g.centre + hx - hy, g.centre + hx + hy, g.centre - hx + hy,
                                 g.centre - hx - hy};
    for (int f = 0; f < 4; ++f) {
      ASSERT_LT(segment, truth.segments.size());
      const WallSegment& s = truth.segments[segment++];
      EXPECT_EQ(s.geom_id, id);
      EXPECT_EQ(s.face_index, f);
      EXPECT_NEAR((s.a - corners[f]).norm(), 0.0, 5e-6) << g.name << " face " << f;
      EXPECT_NEAR((s.b - corners[(f + 1) % 4]).norm(), 0.0, 5e-6) << g.name << " face " << f;
    }
  }
  EXPECT_EQ(segment, truth.segments.size());
  EXPECT_EQ(circle, truth.circles.size());
}

// No two geoms overlap in space, except walls with walls (mitred corners).
void ExpectNoOverlaps(const GeneratedWorld& world) {
  for (size_t i = 0; i < world.geoms.size(); ++i) {
    for (size_t j = i + 1; j < world.geoms.size(); ++j) {
      const WorldGeom& a = world.geoms[i];
      const WorldGeom& b = world.geoms[j];
      if (StartsWith(a.name, "wall_") && StartsWith(b.name, "wall_")) continue;
      if (std::min(a.z_max_m, b.z_max_m) - std::max(a.z_min_m, b.z_min_m) <= 1e-9) continue;
      EXPECT_FALSE(Overlap(a.footprint(), b.footprint(), 1e-6)) << a.name << " and " << b.name;
    }
  }
}

// Cells reachable from `start` through free cells (4-connected) of a 1 cm raster; whether the
// fill reached the raster's border (the world's outside).
struct Fill {
  std::vector<char> reached;
  bool escaped = false;
};

Fill FloodFill(const OccupancyRaster& raster, const Vector2d& start) {
  Fill fill;
  fill.reached.assign(raster.cells.size(), 0);
  const auto cell = raster.CellAt(start);
  if (!cell) {
    fill.escaped = true;
    return fill;
  }
  std::queue<Eigen::Vector2i> queue;
  queue.push(*cell);
  fill.reached[cell->y() * raster.width + cell->x()] = 1;
  while (!queue.empty()) {
    const Eigen::Vector2i c = queue.front();
    queue.pop();
    if (c.x() == 0 || c.y() == 0 || c.x() == raster.width - 1 || c.y() == raster.height - 1) {
      fill.escaped = true;
    }
    for (const Eigen::Vector2i& step : {Eigen::Vector2i(1, 0), Eigen::Vector2i(-1, 0),
                                        Eigen::Vector2i(0, 1), Eigen::Vector2i(0, -1)}) {
      const Eigen::Vector2i n = c + step;
      if (n.x() < 0 || n.y() < 0 || n.x() >= raster.width || n.y() >= raster.height) continue;
      char& seen = fill.reached[n.y() * raster.width + n.x()];
      if (seen || raster.IsOccupied(n.x(), n.y())) continue;
      seen = 1;
      queue.push(n);
    }
  }
  return fill;
}

// Spawn poses: free (clearance from the ground truth, not inside any geom), inside the room, the
// laser at spawn_0 sees geometry within 4 m on at least half its rays.
void ExpectSpawnsFreeAndInside(const mjModel* m, const GeneratedWorld& world, bool closed) {
  const std::vector<msgs::Pose2D> spawns = SpawnPoses(m);
  ASSERT_EQ(spawns.size(), world.spawns.size());
  EXPECT_EQ(spawns[0].x_m, 0.0);
  EXPECT_EQ(spawns[0].y_m, 0.0);
  const GroundTruthWalls truth = ExtractGroundTruthWalls(m);
  const std::vector<UprightGeom> geoms = ExtractUprightGeoms(m);
  const double needed = LargestRobotReachM() + kSpawnMarginM;
  for (size_t k = 0; k < spawns.size(); ++k) {
    const Vector2d p(spawns[k].x_m, spawns[k].y_m);
    double clearance = INFINITY;
    for (const WallSegment& s : truth.segments) {
      clearance = std::min(clearance, DistanceToSegment(p, s.a, s.b));
    }
    for (const WallCircle& c : truth.circles) {
      clearance = std::min(clearance, (p - c.centre).norm() - c.radius_m);
    }
    EXPECT_GE(clearance, needed) << "spawn_" << k;
    for (const UprightGeom& g : geoms) EXPECT_FALSE(g.ContainsXY(p)) << "spawn_" << k;
    EXPECT_TRUE(InsideInteriors(world, p)) << "spawn_" << k;
  }
  OccupancyRasterOptions options;
  options.resolution_m = 0.01;
  options.height_m = 0.2;
  const OccupancyRaster raster = RasteriseOccupancy(m, options);
  const Fill fill = FloodFill(raster, Vector2d::Zero());
  EXPECT_EQ(fill.escaped, !closed) << (closed ? "a closed world leaks" : "an open world is shut");
  for (size_t k = 1; k < spawns.size(); ++k) {
    const auto cell = raster.CellAt({spawns[k].x_m, spawns[k].y_m});
    ASSERT_TRUE(cell.has_value());
    EXPECT_TRUE(fill.reached[cell->y() * raster.width + cell->x()])
        << "spawn_" << k << " is not connected to spawn_0";
  }
  // The laser's rays at 0.34 m from spawn_0 (static geometry only).
  MjDataPtr data(mj_makeData(m));
  mj_forward(m, data.get());
  int hits = 0;
  for (int i = 0; i < 360; ++i) {
    const mjtNum origin[3] = {0, 0, 0.34};
    const mjtNum direction[3] = {std::cos(i * kPi / 180), std::sin(i * kPi / 180), 0};
    int geom = -1;
    const mjtNum d = mj_ray(m, data.get(), origin, direction, nullptr, 1, -1, &geom);
    hits += d >= 0 && d <= 4.0;
  }
  EXPECT_GE(hits, 180);
}

// Both robots: the P3-DX at every spawn pose, the Magellan Pro at spawn_0. Only the floor is
// touched, no MuJoCo warning, and after 1 s at rest the robot is where it was put.
void ExpectRobotsRestAtSpawns(const fs::path& mjcf, size_t n_spawns) {
  for (const RobotCatalogEntry& robot : RobotCatalog()) {
    const size_t n = robot.name == "p3dx" ? n_spawns : 1;
    const std::vector<msgs::Pose2D> spawns = SpawnPoses(LoadModelFromFile(mjcf.string()).get());
    for (size_t k = 0; k < n; ++k) {
      SCOPED_TRACE(robot.name + " at spawn_" + std::to_string(k));
      SceneOptions options;
      options.world_mjcf = mjcf;
      options.robot_mjcf = robot.mjcf;
      options.spawn = spawns[k];
      const std::string warning_before = LastMujocoWarning();
      Scene scene(options);
      for (int step = 0; step < 100; ++step) {
        scene.Step();
        const mjData* d = scene.data();
        for (int c = 0; c < d->ncon; ++c) {
          const int g1 = d->contact[c].geom1, g2 = d->contact[c].geom2;
          const int other = scene.IsRobotGeom(g1) ? g2 : g1;
          ASSERT_EQ(scene.model()->geom_type[other], mjGEOM_PLANE)
              << "touches " << mj_id2name(scene.model(), mjOBJ_GEOM, other);
        }
      }
      const msgs::Pose2D pose = scene.TruePose();
      EXPECT_NEAR(pose.x_m, spawns[k].x_m, 5e-3);
      EXPECT_NEAR(pose.y_m, spawns[k].y_m, 5e-3);
      EXPECT_NEAR(std::remainder(pose.theta_rad - spawns[k].theta_rad, 2 * kPi), 0.0, 5e-3);
      EXPECT_EQ(LastMujocoWarning(), warning_before);
    }
  }
}

#define EXPECT_IN(value, lo, hi)          \
  do {                                    \
    const double v_ = (value);            \
    EXPECT_GE(v_, (lo)-1e-9) << #value;   \
    EXPECT_LE(v_, (hi) + 1e-9) << #value; \
  } while (0)

int CountNamed(const GeneratedWorld& world, const std::string& prefix) {
  int n = 0;
  for (const WorldGeom& g : world.geoms) n += StartsWith(g.name, prefix);
  return n;
}

// The sidecar's parameters lie in docs/worlds.md's ranges and agree with the geometry.
void ExpectParametersInRange(const std::string& family, const YAML::Node& p,
                             const GeneratedWorld& world) {
  const int walls = CountNamed(world, "wall_");
  if (family == "room") {
    const std::string shape = p["shape"].as<std::string>();
    const double w = p["width_m"].as<double>(), d = p["depth_m"].as<double>();
    EXPECT_IN(w, 3, 10);
    EXPECT_IN(d, 3, 10);
    EXPECT_IN(p["rotation_deg"].as<double>(), 0, 360);
    EXPECT_EQ(walls, shape == "rectangle" ? 4 : shape == "L" ? 6 : 8) << shape;
    if (shape == "L") {
      EXPECT_IN(p["notch_width_m"].as<double>(), 0.6, w - 1.2);
      EXPECT_IN(p["notch_depth_m"].as<double>(), 0.6, d - 1.2);
    } else if (shape == "T") {
      EXPECT_IN(p["stem_width_m"].as<double>(), 1.2, w - 1.2);
      EXPECT_IN(p["bar_depth_m"].as<double>(), 1.2, d - 1.2);
    } else {
      EXPECT_EQ(shape, "rectangle");
    }
  } else if (family == "doorways") {
    EXPECT_IN(p["width_m"].as<double>(), 3, 7);
    EXPECT_IN(p["depth_m"].as<double>(), 3, 7);
    const YAML::Node openings = p["openings"];
    EXPECT_IN(openings.size(), 1, 3);
    std::set<int> used;
    int expected_walls = 4;
    for (const YAML::Node& o : openings) {
      EXPECT_IN(o["width_m"].as<double>(), 0.3, 1.2);
      EXPECT_GE(o["from_m"].as<double>(), 0.3);
      EXPECT_TRUE(used.insert(o["wall"].as<int>()).second) << "two openings in one wall";
      const std::string behind = o["behind"].as<std::string>();
      EXPECT_TRUE(behind == "nothing" || behind == "panel" || behind == "alcove") << behind;
      expected_walls += 1 + (behind == "panel" ? 1 : behind == "alcove" ? 3 : 0);
      if (behind == "panel") {
        EXPECT_IN(o["panel_distance_m"].as<double>(), 0.3, 1.5);
      }
      if (behind == "alcove") {
        EXPECT_IN(o["alcove_depth_m"].as<double>(), 1.0, 3.0);
      }
    }
    EXPECT_EQ(walls, expected_walls);
  } else if (family == "columns") {
    EXPECT_IN(p["width_m"].as<double>(), 3, 8);
    EXPECT_IN(p["columns"].size(), 1, 6);
    EXPECT_IN(p["tables"].size(), 0, 2);
    for (const YAML::Node& c : p["columns"]) {
      EXPECT_IN(c[0].as<double>(), 0.03, 0.3);
    }
    for (const YAML::Node& t : p["tables"]) {
      EXPECT_IN(t["leg_radius_m"].as<double>(), 0.01, 0.03);
      EXPECT_IN(t["height_m"].as<double>(), 0.7, 0.76);
    }
    EXPECT_EQ(CountNamed(world, "column_"), static_cast<int>(p["columns"].size()));
    EXPECT_EQ(CountNamed(world, "table_"), 5 * static_cast<int>(p["tables"].size()));
    for (const WorldGeom& g : world.geoms) {
      if (StartsWith(g.name, "column_")) {
        EXPECT_IN(g.radius_m, 0.03, 0.3);
      }
      if (g.name.find("_leg_") != std::string::npos) {
        EXPECT_IN(g.radius_m, 0.01, 0.03);
      }
    }
  } else if (family == "clutter") {
    EXPECT_IN(p["boxes"].size(), 2, 8);
    for (const YAML::Node& b : p["boxes"]) {
      EXPECT_IN(b[0].as<double>(), 0.1, 0.6);
      EXPECT_IN(b[1].as<double>(), 0.1, 0.6);
      EXPECT_IN(b[2].as<double>(), 0.4, 1.0);
    }
    EXPECT_EQ(CountNamed(world, "obstacle_"), static_cast<int>(p["boxes"].size()));
    for (const WorldGeom& g : world.geoms) {
      if (StartsWith(g.name, "obstacle_")) {
        EXPECT_IN(2 * g.half_size.maxCoeff(), 0.1, 0.6);
      }
    }
  } else if (family == "stubs") {
    const int corners = p["corners"].as<int>();
    EXPECT_IN(corners, 4, 5);
    for (const YAML::Node& a : p["corner_angles_deg"]) {
      EXPECT_IN(a.as<double>(), 60, 120);
    }
    EXPECT_IN(p["chamfers"].size(), 0, 2);
    for (const YAML::Node& c : p["chamfers"]) {
      EXPECT_IN(c[1].as<double>(), 0.2, 0.6);
    }
    EXPECT_IN(p["stubs"].size(), 1, 3);
    for (const YAML::Node& s : p["stubs"]) {
      EXPECT_IN(s[2].as<double>(), 0.2, 0.8);
    }
    EXPECT_EQ(walls, corners + static_cast<int>(p["chamfers"].size() + p["stubs"].size()));
  } else if (family == "corridor") {
    const std::string junction = p["junction"].as<std::string>();
    const size_t arms = junction == "straight" || junction == "L" ? 2 : junction == "T" ? 3 : 4;
    EXPECT_TRUE(junction == "straight" || junction == "L" || junction == "T" || junction == "X");
    EXPECT_IN(p["width_m"].as<double>(), 1.0, 2.0);
    EXPECT_EQ(p["arm_lengths_m"].size(), arms);
    for (const YAML::Node& l : p["arm_lengths_m"]) {
      EXPECT_IN(l.as<double>(), 1.5, 5.0);
    }
    EXPECT_IN(p["side_openings"].size(), 0, 3);
    for (const YAML::Node& o : p["side_openings"]) {
      EXPECT_IN(o["width_m"].as<double>(), 0.6, 1.2);
    }
  } else if (family == "seed001") {
    EXPECT_IN(p["width_m"].as<double>(), 3.2, 3.8);
    EXPECT_IN(p["depth_m"].as<double>(), 2.8, 3.2);
    EXPECT_EQ(walls, 4);
    const YAML::Node obstacles = p["obstacles"];
    EXPECT_IN(obstacles.size(), 0, 3);
    int boxes = 0;
    for (const YAML::Node& o : obstacles) {
      const std::string kind = o["kind"].as<std::string>();
      boxes += kind == "L" ? 2 : 1;
      if (kind != "L") {
        EXPECT_IN(o["size_m"][0].as<double>(), 0.3, 0.9);
        EXPECT_IN(o["size_m"][1].as<double>(), 0.3, 0.9);
      }
      if (o["gap_m"]) {
        EXPECT_IN(o["gap_m"].as<double>(), 0.3, 1.2);
      }
    }
    EXPECT_EQ(CountNamed(world, "obstacle_"), boxes);
    for (const WorldGeom& g : world.geoms) {
      if (StartsWith(g.name, "obstacle_")) {
        EXPECT_NEAR(g.z_max_m, 0.6, 1e-12);
      }
    }
  } else if (family == "office") {
    EXPECT_IN(p["width_m"].as<double>(), 15, 22);
    EXPECT_IN(p["depth_m"].as<double>(), 10, 14);
    EXPECT_IN(p["corridor_width_m"].as<double>(), 1.4, 2.0);
    EXPECT_GE(p["rooms"].size(), 4u);
    Eigen::AlignedBox2d bounds;
    for (const WorldGeom& g : world.geoms) {
      if (!StartsWith(g.name, "wall_")) continue;
      for (const Vector2d& c : g.footprint().corners) bounds.extend(c);
    }
    EXPECT_GE(bounds.sizes().x(), 15.0);
    EXPECT_GE(bounds.sizes().y(), 10.0);
  } else {
    ADD_FAILURE() << "no range checks for family " << family;
  }
}

class GeneratedWorldsTest : public ::testing::TestWithParam<std::string> {};

TEST_P(GeneratedWorldsTest, EveryWorldIsSound) {
  const std::string family = GetParam();
  const int count = EnvironmentInt("PLYWOOD_WORLDS_COUNT", 20, 1);
  const int seed = EnvironmentInt("PLYWOOD_WORLDS_SEED", 1, 0);
  const fs::path dir = testing::MakeTempDir("generated_worlds_" + family);
  GenerateWorldsOptions options;
  options.family = family;
  options.count = count;
  options.seed = seed;
  options.out_dir = dir;
  options.check_with_mujoco = false;  // checked here, independently
  const auto files = GenerateWorlds(options);
  ASSERT_EQ(files.size(), static_cast<size_t>(count));
  int closed = 0;
  for (int i = 0; i < count; ++i) {
    SCOPED_TRACE(files[i].mjcf.filename().string());
    const GeneratedWorld world = GenerateWorld(family, seed, i);
    const YAML::Node sidecar = YAML::LoadFile(files[i].sidecar.string());
    EXPECT_EQ(sidecar["family"].as<std::string>(), family);
    EXPECT_EQ(sidecar["seed"].as<int>(), seed);
    EXPECT_EQ(sidecar["index"].as<int>(), i);
    EXPECT_EQ(sidecar["spawns"].size(), world.spawns.size());
    const std::string warning_before = LastMujocoWarning();
    const MjModelPtr model = LoadModelFromFile(files[i].mjcf.string());
    EXPECT_EQ(LastMujocoWarning(), warning_before);
    ExpectGeometryMatches(model.get(), world);
    ExpectNoOverlaps(world);
    ExpectSpawnsFreeAndInside(model.get(), world, sidecar["closed"].as<bool>());
    ExpectRobotsRestAtSpawns(files[i].mjcf, world.spawns.size());
    ExpectParametersInRange(family, sidecar["parameters"], world);
    closed += sidecar["closed"].as<bool>();
  }
  std::printf("%s seed %d: %d of %d worlds closed\n", family.c_str(), seed, closed, count);
}

std::vector<std::string> FamilyNames() {
  std::vector<std::string> names;
  for (const WorldFamily& f : WorldFamilies()) names.push_back(f.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(Families, GeneratedWorldsTest, ::testing::ValuesIn(FamilyNames()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace plywood::sim::worldgen
