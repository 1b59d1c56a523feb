#include "sim/world/contact_filter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "sim/config/robot_catalog.h"
#include "sim/world/scene.h"

namespace plywood::sim {
namespace {

// Geom pairs in contact after a full collision pass with `filter` installed, robot at `qpos`.
// Each pass starts from freshly reset data: MuJoCo 2.2.2's collision pass is not a pure function
// of qpos (a second mj_forward at the same pose can report fewer plane contacts), so both filters
// must see the same history.
std::set<std::pair<int, int>> Contacts(const mjModel* m, mjData* d, const std::vector<double>& qpos,
                                       mjfConFilt filter) {
  mj_resetData(m, d);
  std::copy(qpos.begin(), qpos.end(), d->qpos);
  mjcb_contactfilter = filter;
  mj_forward(m, d);
  mjcb_contactfilter = nullptr;
  std::set<std::pair<int, int>> pairs;
  for (int i = 0; i < d->ncon; ++i) pairs.emplace(d->contact[i].geom1, d->contact[i].geom2);
  return pairs;
}

void ExpectSameContactsAsTheDefaultFilter(const std::string& robot) {
  SceneOptions options;
  options.world_mjcf = DataRoot() / "worlds" / "seed000_room_3.xml";
  options.robot_mjcf = FindRobot(robot).mjcf;
  Scene scene(options);
  const mjModel* m = scene.model();
  mjData* d = scene.mutable_data();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> x(-1.8, 2.3), y(-1.5, 1.8), yaw(-3.14, 3.14);
  int poses_with_wall_contact = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // Anywhere in and around the room, including poses that push the robot into walls.
    std::vector<double> qpos(m->qpos0, m->qpos0 + m->nq);
    qpos[0] = x(rng);
    qpos[1] = y(rng);
    const double a = yaw(rng);
    qpos[3] = std::cos(a / 2.0);
    qpos[6] = std::sin(a / 2.0);
    const auto expected = Contacts(m, d, qpos, nullptr);
    EXPECT_EQ(Contacts(m, d, qpos, TightContactFilter), expected) << robot << " trial " << trial;
    poses_with_wall_contact += std::any_of(expected.begin(), expected.end(), [&](const auto& pair) {
      return m->geom_type[pair.first] != mjGEOM_PLANE && m->geom_type[pair.second] != mjGEOM_PLANE;
    });
  }
  EXPECT_GT(poses_with_wall_contact, 20) << robot << ": the trial poses must include wall contacts";
}

TEST(TightContactFilterTest, KeepsEveryContactTheDefaultFilterFinds) {
  ExpectSameContactsAsTheDefaultFilter("p3dx");
  ExpectSameContactsAsTheDefaultFilter("magellan_pro");
}

TEST(TightContactFilterTest, KeepsEveryContactWithTableLegsAndColumns) {
  // The office's cylinders (table legs, columns), approached from every side and distance.
  for (const std::string robot : {"p3dx", "magellan_pro"}) {
    SceneOptions options;
    options.world_mjcf = DataRoot() / "worlds" / "office.xml";
    options.robot_mjcf = FindRobot(robot).mjcf;
    Scene scene(options);
    const mjModel* m = scene.model();
    mjData* d = scene.mutable_data();
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int poses_touching_a_cylinder = 0, cylinders = 0;
    for (int g = 0; g < m->ngeom; ++g) {
      if (scene.IsRobotGeom(g) || m->geom_type[g] != mjGEOM_CYLINDER) continue;
      ++cylinders;
      for (int trial = 0; trial < 8; ++trial) {
        std::vector<double> qpos(m->qpos0, m->qpos0 + m->nq);
        const double bearing = 6.283 * unit(rng), distance = m->geom_size[3 * g] + 0.5 * unit(rng);
        qpos[0] = d->geom_xpos[3 * g] + distance * std::cos(bearing);
        qpos[1] = d->geom_xpos[3 * g + 1] + distance * std::sin(bearing);
        const double yaw = 6.283 * unit(rng);
        qpos[3] = std::cos(yaw / 2.0);
        qpos[6] = std::sin(yaw / 2.0);
        const auto expected = Contacts(m, d, qpos, nullptr);
        EXPECT_EQ(Contacts(m, d, qpos, TightContactFilter), expected) << robot << " geom " << g;
        poses_touching_a_cylinder +=
            std::any_of(expected.begin(), expected.end(),
                        [&](const auto& pair) { return pair.first == g || pair.second == g; });
      }
    }
    EXPECT_GT(cylinders, 10);
    EXPECT_GT(poses_touching_a_cylinder, cylinders) << robot;
  }
}

TEST(TightContactFilterTest, DropsARobotGeomFarFromALongWall) {
  SceneOptions options;
  options.world_mjcf = DataRoot() / "worlds" / "office.xml";
  options.robot_mjcf = FindRobot("p3dx").mjcf;
  options.spawn = {-6.5, 0.0, 0.0};
  Scene scene(options);
  const int chassis = mj_name2id(scene.model(), mjOBJ_GEOM, "chassis");
  int rejected = 0, boxes = 0;
  for (int g = 0; g < scene.model()->ngeom; ++g) {
    if (scene.IsRobotGeom(g) || scene.model()->geom_type[g] != mjGEOM_BOX) continue;
    ++boxes;
    rejected += TightContactFilter(scene.model(), scene.mutable_data(), chassis, g);
  }
  // At the corridor's west end only the nearby walls can be touched.
  EXPECT_GT(rejected, boxes - 6);
}

}  // namespace
}  // namespace plywood::sim
