#include "sim/world/near_contact_pairs.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "sim/config/robot_catalog.h"
#include "sim/world/contact_filter.h"
#include "sim/world/scene.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::sim {
namespace {

struct Compiled {
  MjModelPtr model;
  MjDataPtr data;
  int base = -1;
};

Compiled Compile(const std::filesystem::path& world, const std::string& robot) {
  Compiled c;
  c.model = LoadModelFromString(
      ComposeSceneMjcf(world, FindRobot(robot).mjcf, NearContactPairs::kCapacity),
      (world.parent_path() / "__near_pairs_test__.xml").string());
  c.data.reset(mj_makeData(c.model.get()));
  mj_resetData(c.model.get(), c.data.get());
  mj_kinematics(c.model.get(), c.data.get());
  c.base = mj_name2id(c.model.get(), mjOBJ_BODY, "base");
  return c;
}

void SetPose(const mjModel* m, mjData* d, double x, double y, double yaw) {
  mj_resetData(m, d);  // a collision pass is not a pure function of qpos: same history for both
  d->qpos[0] = x;
  d->qpos[1] = y;
  d->qpos[3] = std::cos(yaw / 2.0);
  d->qpos[6] = std::sin(yaw / 2.0);
}

// Every contact field the solver reads, as raw bytes.
std::vector<mjContact> Contacts(const mjData* d) {
  return std::vector<mjContact>(d->contact, d->contact + d->ncon);
}

bool SameBits(const std::vector<mjContact>& a, const std::vector<mjContact>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const mjContact &x = a[i], &y = b[i];
    const bool same = x.geom1 == y.geom1 && x.geom2 == y.geom2 && x.dim == y.dim &&
                      std::memcmp(&x.dist, &y.dist, sizeof x.dist) == 0 &&
                      std::memcmp(x.pos, y.pos, sizeof x.pos) == 0 &&
                      std::memcmp(x.frame, y.frame, sizeof x.frame) == 0 &&
                      std::memcmp(x.friction, y.friction, sizeof x.friction) == 0 &&
                      std::memcmp(x.solref, y.solref, sizeof x.solref) == 0 &&
                      std::memcmp(x.solimp, y.solimp, sizeof x.solimp) == 0 &&
                      std::memcmp(&x.includemargin, &y.includemargin, sizeof x.includemargin) == 0;
    if (!same) return false;
  }
  return true;
}

TEST(NearContactPairsTest, GivesBitwiseTheContactsOfMuJoCosOwnSearch) {
  InstallTightContactFilter();
  for (const std::string robot : {"p3dx", "magellan_pro"}) {
    Compiled c = Compile(DataRoot() / "worlds" / "office.xml", robot);
    const mjModel* m = c.model.get();
    mjData* d = c.data.get();
    NearContactPairs pairs(c.model.get(), d, c.base);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int poses_touching_world = 0;
    // Near every wall, table leg and column, from every side, many of them pushed into it.
    for (int g = 0; g < m->ngeom; ++g) {
      if (m->geom_group[g] == Scene::kRobotGeomGroup || m->geom_type[g] == mjGEOM_PLANE) continue;
      for (int trial = 0; trial < 3; ++trial) {
        const double bearing = 6.283 * unit(rng), distance = 0.6 * unit(rng);
        const double x = d->geom_xpos[3 * g] + distance * std::cos(bearing);
        const double y = d->geom_xpos[3 * g + 1] + distance * std::sin(bearing);
        const double yaw = 6.283 * unit(rng);
        SetPose(m, d, x, y, yaw);
        mj_forward(m, d);
        const std::vector<mjContact> expected = Contacts(d);
        SetPose(m, d, x, y, yaw);
        {
          const NearContactPairs::Active active = pairs.Activate(d);
          mj_forward(m, d);
        }
        EXPECT_GE(pairs.last_pair_count(), 0);
        EXPECT_TRUE(SameBits(Contacts(d), expected)) << robot << " near geom " << g;
        for (const mjContact& contact : expected) {
          if (m->geom_type[contact.geom1] != mjGEOM_PLANE &&
              m->geom_type[contact.geom2] != mjGEOM_PLANE) {
            ++poses_touching_world;
            break;
          }
        }
      }
    }
    EXPECT_GT(poses_touching_world, 40) << robot << ": the poses must include wall contacts";
    // Left as it found the model: the placeholders back, MuJoCo's own search on.
    EXPECT_EQ(m->npair, NearContactPairs::kCapacity);
    EXPECT_EQ(m->opt.collision, mjCOL_ALL);
  }
}

// A 4 m square room, plus `far_boxes` boxes in a row 10 m and more away.
std::string Room(int far_boxes) {
  std::string text =
      "<mujoco><worldbody>\n"
      "<geom name=\"floor\" type=\"plane\" size=\"100 100 0.1\"/>\n"
      "<geom type=\"box\" pos=\"0 2 0.5\" size=\"2 0.01 0.5\"/>\n"
      "<geom type=\"box\" pos=\"0 -2 0.5\" size=\"2 0.01 0.5\"/>\n"
      "<geom type=\"box\" pos=\"2 0 0.5\" size=\"0.01 2 0.5\"/>\n"
      "<geom type=\"box\" pos=\"-2 0 0.5\" size=\"0.01 2 0.5\"/>\n";
  for (int i = 0; i < far_boxes; ++i) {
    text += "<geom type=\"box\" pos=\"" + std::to_string(10 + 0.5 * (i % 40)) + " " +
            std::to_string(0.5 * (i / 40)) + " 0.5\" size=\"0.1 0.1 0.5\"/>\n";
  }
  return text + "</worldbody></mujoco>\n";
}

TEST(NearContactPairsTest, PairsOnlyWhatIsNearTheRobotWhateverTheWorldsSize) {
  const auto dir = testing::MakeTempDir("near_contact_pairs");
  int counts[2];
  for (int k = 0; k < 2; ++k) {
    const auto world =
        testing::WriteFile(dir / ("room" + std::to_string(k) + ".xml"), Room(k == 0 ? 0 : 400));
    Compiled c = Compile(world, "p3dx");
    mjData* d = c.data.get();
    NearContactPairs pairs(c.model.get(), d, c.base);
    SetPose(c.model.get(), d, 1.85, 0.0, 0.0);  // pushed into the east wall
    {
      const NearContactPairs::Active active = pairs.Activate(d);
      mj_forward(c.model.get(), d);
    }
    counts[k] = pairs.last_pair_count();
    bool wall_contact = false;
    for (int i = 0; i < d->ncon; ++i) {
      wall_contact |= c.model->geom_type[d->contact[i].geom1] == mjGEOM_BOX ||
                      c.model->geom_type[d->contact[i].geom2] == mjGEOM_BOX;
    }
    EXPECT_TRUE(wall_contact) << "the robot pushed into the east wall must touch it";
  }
  // The floor and the east wall with each of the P3-DX's collidable geoms, in both worlds.
  EXPECT_GT(counts[0], 0);
  EXPECT_EQ(counts[1], counts[0]);
  EXPECT_LE(counts[0], 2 * 5);
}

}  // namespace
}  // namespace plywood::sim
