// Compiles every shipped MJCF file (models/ alone, worlds/ alone and with each robot at every
// spawn pose the world declares) and checks the conventions in worlds/README.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/world/ground_truth_walls.h"
#include "sim/world/mujoco_handles.h"
#include "sim/world/scene.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::sim {
namespace {

namespace fs = std::filesystem;
using Eigen::Vector2d;

// Every spawn pose leaves at least this much room around the robot's origin; the P3-DX reaches
// 0.345 m from its origin (chassis corners), the Magellan Pro 0.21 m.
constexpr double kSpawnClearanceM = 0.4;

std::vector<fs::path> XmlFilesIn(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() == ".xml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

struct Compiled {
  MjModelPtr model;
  std::string message;  // what MuJoCo left in the error buffer: compiler warnings on success
};

// Like LoadModelFromString/LoadModelFromFile, but keeps the compiler's message on success.
Compiled Compile(const fs::path& path, const std::string* text = nullptr) {
  InstallMujocoErrorHandlers();
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  if (text != nullptr) {
    const std::string name = path.filename().string();
    EXPECT_EQ(mj_makeEmptyFileVFS(&vfs, name.c_str(), static_cast<int>(text->size())), 0);
    std::memcpy(vfs.filedata[vfs.nfile - 1], text->data(), text->size());
  }
  char error[1024] = "";
  Compiled out;
  out.model.reset(mj_loadXML(path.c_str(), text != nullptr ? &vfs : nullptr, error, sizeof(error)));
  out.message = error;
  mj_deleteVFS(&vfs);
  return out;
}

std::vector<msgs::Pose2D> SpawnPoses(const mjModel* m) {
  std::vector<msgs::Pose2D> spawns;
  for (int i = 0;; ++i) {
    const int id = mj_name2id(m, mjOBJ_NUMERIC, ("spawn_" + std::to_string(i)).c_str());
    if (id < 0) break;
    EXPECT_EQ(m->numeric_size[id], 3) << "spawn_" << i << ": x_m y_m yaw_deg";
    const mjtNum* v = m->numeric_data + m->numeric_adr[id];
    spawns.push_back({v[0], v[1], v[2] * M_PI / 180.0});
  }
  return spawns;
}

double DistanceToSegment(const Vector2d& p, const WallSegment& s) {
  const Vector2d d = s.b - s.a;
  const double t = std::clamp((p - s.a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (s.a + t * d - p).norm();
}

double Clearance(const GroundTruthWalls& walls, const Vector2d& p) {
  double clearance = INFINITY;
  for (const WallSegment& s : walls.segments) {
    clearance = std::min(clearance, DistanceToSegment(p, s));
  }
  for (const WallCircle& c : walls.circles) {
    clearance = std::min(clearance, (p - c.centre).norm() - c.radius_m);
  }
  return clearance;
}

bool StartsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

TEST(WorldFilesTest, EveryModelCompilesWithoutWarnings) {
  const auto files = XmlFilesIn(testing::SourceRoot() / "models");
  ASSERT_GE(files.size(), 2u);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const std::string warning_before = LastMujocoWarning();
    const Compiled c = Compile(file);
    ASSERT_NE(c.model, nullptr) << c.message;
    EXPECT_EQ(c.message, "");
    EXPECT_EQ(LastMujocoWarning(), warning_before);
    // The world's ground truth relies on this: every robot geom is in the robot's group.
    for (int g = 0; g < c.model->ngeom; ++g) {
      EXPECT_EQ(c.model->geom_group[g], Scene::kRobotGeomGroup) << "geom " << g;
    }
  }
}

TEST(WorldFilesTest, EveryWorldCompilesAndFollowsTheWorldConventions) {
  const auto files = XmlFilesIn(testing::SourceRoot() / "worlds");
  ASSERT_GE(files.size(), 11u);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const std::string name = file.stem().string();
    const std::string warning_before = LastMujocoWarning();
    const Compiled c = Compile(file);
    ASSERT_NE(c.model, nullptr) << c.message;
    EXPECT_EQ(c.message, "");
    EXPECT_EQ(LastMujocoWarning(), warning_before);
    const mjModel* m = c.model.get();
    EXPECT_EQ(m->nbody, 1) << "shipped worlds keep every geom in worldbody";
    EXPECT_EQ(m->njnt, 0);
    EXPECT_FALSE(SpawnPoses(m).empty()) << "declare at least <numeric name=\"spawn_0\">";

    const int floor = mj_name2id(m, mjOBJ_GEOM, "floor");
    ASSERT_GE(floor, 0);
    EXPECT_EQ(m->geom_type[floor], mjGEOM_PLANE);
    EXPECT_EQ(m->geom_pos[3 * floor + 2], 0.0);
    int planes = 0;
    for (int g = 0; g < m->ngeom; ++g) {
      planes += m->geom_type[g] == mjGEOM_PLANE;
      EXPECT_NE(mj_id2name(m, mjOBJ_GEOM, g), nullptr) << "geom " << g << " has no name";
      EXPECT_NE(m->geom_group[g], Scene::kRobotGeomGroup) << "geom " << g;
    }
    EXPECT_EQ(planes, 1);

    // Everything but the floor is an upright box or cylinder standing on it.
    const std::vector<UprightGeom> geoms = ExtractUprightGeoms(m);
    EXPECT_EQ(static_cast<int>(geoms.size()), m->ngeom - 1);
    EXPECT_TRUE(ExtractGroundTruthWalls(m).unrepresented_geom_ids.empty());
    Eigen::AlignedBox2d bounds;
    int walls = 0;
    for (const UprightGeom& g : geoms) {
      const std::string geom_name = mj_id2name(m, mjOBJ_GEOM, g.geom_id);
      EXPECT_GE(g.z_min_m, -1e-12) << geom_name << " reaches below the floor";
      if (!StartsWith(geom_name, "wall_")) continue;
      ++walls;
      // 18 mm plywood, 1 m tall.
      ASSERT_EQ(g.shape, UprightGeom::Shape::kBox) << geom_name;
      EXPECT_NEAR(g.half_size_xy.minCoeff(), 0.009, 1e-12) << geom_name;
      EXPECT_NEAR(g.z_max_m, 1.0, 1e-12) << geom_name;
      for (const double sx : {-1.0, 1.0}) {
        for (const double sy : {-1.0, 1.0}) {
          const Vector2d corner =
              g.centre_W + g.R_WG * Vector2d(sx * g.half_size_xy.x(), sy * g.half_size_xy.y());
          bounds.extend(corner);
          // Seed 000's rooms: every wall within 4 m of the sensor at the origin.
          if (StartsWith(name, "seed000_")) {
            EXPECT_LE(corner.norm(), 4.0) << geom_name;
          }
        }
      }
    }
    EXPECT_GE(walls, 4);
    if (StartsWith(name, "seed000_")) {
      EXPECT_LE(walls, 8);
    }
    if (name == "office") {
      EXPECT_GE(bounds.sizes().x(), 15.0);
      EXPECT_GE(bounds.sizes().y(), 10.0);
      EXPECT_GE(m->ngeom, 60);
      EXPECT_LE(m->ngeom, 120);
    }
    if (name == "hall") {
      EXPECT_GE(bounds.sizes().minCoeff(), 6.0 + 2 * 0.018);
      EXPECT_EQ(m->ngeom, 5);  // floor and four walls
    }
  }
}

// Composes each world with each robot at every declared spawn pose: the model compiles without
// warnings, the robot touches nothing but the floor, has kSpawnClearanceM around it, and stays
// put for 1 s with the motors at rest.
TEST(WorldFilesTest, EveryWorldComposesWithTheRobotsAtItsSpawnPoses) {
  const fs::path root = testing::SourceRoot();
  for (const fs::path& world : XmlFilesIn(root / "worlds")) {
    const MjModelPtr world_model = LoadModelFromFile(world.string());
    const GroundTruthWalls walls = ExtractGroundTruthWalls(world_model.get());
    const std::vector<msgs::Pose2D> spawns = SpawnPoses(world_model.get());
    for (const std::string robot : {"p3dx", "magellan_pro"}) {
      const fs::path robot_file = root / "models" / (robot + ".xml");
      const std::string text = ComposeSceneMjcf(world, robot_file);
      const Compiled composed = Compile(world.parent_path() / "__plywood_scene__.xml", &text);
      ASSERT_NE(composed.model, nullptr) << world << " + " << robot << ": " << composed.message;
      EXPECT_EQ(composed.message, "") << world << " + " << robot;
      // Every spawn with the P3-DX (the larger robot), the first one with the Magellan Pro.
      const size_t n_spawns = robot == "p3dx" ? spawns.size() : 1;
      for (size_t i = 0; i < n_spawns; ++i) {
        const msgs::Pose2D spawn = spawns[i];
        SCOPED_TRACE(world.filename().string() + " + " + robot + " at spawn_" + std::to_string(i));
        EXPECT_GE(Clearance(walls, {spawn.x_m, spawn.y_m}), kSpawnClearanceM);
        const std::string warning_before = LastMujocoWarning();
        SceneOptions options;
        options.world_mjcf = world;
        options.robot_mjcf = robot_file;
        options.spawn = spawn;
        Scene scene(options);
        const mjModel* m = scene.model();
        const mjData* d = scene.data();
        for (int c = 0; c < d->ncon; ++c) {
          const int g1 = d->contact[c].geom1, g2 = d->contact[c].geom2;
          const int other = scene.IsRobotGeom(g1) ? g2 : g1;
          EXPECT_EQ(m->geom_type[other], mjGEOM_PLANE)
              << "robot touches " << mj_id2name(m, mjOBJ_GEOM, other);
        }
        for (int step = 0; step < 100; ++step) scene.Step();
        const msgs::Pose2D pose = scene.TruePose();
        EXPECT_NEAR(pose.x_m, spawn.x_m, 5e-3);
        EXPECT_NEAR(pose.y_m, spawn.y_m, 5e-3);
        EXPECT_NEAR(std::remainder(pose.theta_rad - spawn.theta_rad, 2 * M_PI), 0.0, 5e-3);
        for (int w = 0; w < mjNWARNING; ++w) {
          EXPECT_EQ(d->warning[w].number, 0) << "MuJoCo warning " << w;
        }
        EXPECT_EQ(LastMujocoWarning(), warning_before);
      }
    }
  }
}

}  // namespace
}  // namespace plywood::sim
