#include "sim/world/static_geom_step.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#include "sim/config/robot_catalog.h"
#include "sim/world/contact_filter.h"
#include "sim/world/draw_only_geoms.h"
#include "sim/world/near_contact_pairs.h"
#include "sim/world/scene.h"
#include "sim/world/step_skipped_sites.h"

namespace plywood::sim {
namespace {

// The office and a robot as Scene composes them, with its near-contact pairs.
struct Compiled {
  MjModelPtr model;
  MjDataPtr data;
  std::unique_ptr<NearContactPairs> pairs;

  explicit Compiled(const std::string& robot) {
    const std::filesystem::path world = DataRoot() / "worlds" / "office.xml";
    model = LoadModelFromString(
        ComposeSceneMjcf(world, FindRobot(robot).mjcf, NearContactPairs::kCapacity),
        (world.parent_path() / "__static_geom_step_test__.xml").string());
    data.reset(mj_makeData(model.get()));
    // In the corridor where the default experiment starts, facing its north wall.
    data->qpos[0] = -6.5;
    data->qpos[3] = std::cos(M_PI / 4);
    data->qpos[6] = std::sin(M_PI / 4);
    mj_forward(model.get(), data.get());
    pairs = std::make_unique<NearContactPairs>(model.get(), data.get(),
                                               mj_name2id(model.get(), mjOBJ_BODY, "base"));
  }
};

template <typename T>
bool SameBytes(const T* a, const T* b, int n) {
  return std::memcmp(a, b, sizeof(T) * n) == 0;
}

// Every contact field the solver reads, bit for bit (the struct's padding is not compared).
bool SameContacts(const mjData* a, const mjData* b) {
  if (a->ncon != b->ncon) return false;
  for (int i = 0; i < a->ncon; ++i) {
    const mjContact &x = a->contact[i], &y = b->contact[i];
    if (x.geom1 != y.geom1 || x.geom2 != y.geom2 || x.dim != y.dim || x.exclude != y.exclude ||
        x.efc_address != y.efc_address || !SameBytes(&x.dist, &y.dist, 1) ||
        !SameBytes(x.pos, y.pos, 3) || !SameBytes(x.frame, y.frame, 9) ||
        !SameBytes(x.friction, y.friction, 5) || !SameBytes(x.solref, y.solref, mjNREF) ||
        !SameBytes(x.solimp, y.solimp, mjNIMP) || !SameBytes(&x.mu, &y.mu, 1) ||
        !SameBytes(&x.includemargin, &y.includemargin, 1)) {
      return false;
    }
  }
  return true;
}

// Both robots driven by the same random wheel commands, into the corridor walls and furniture
// (reversing and turning): every step's qpos, qvel, accelerations and contacts bit for bit.
TEST(StaticGeomStepTest, BitIdenticalToMjStepOverThousandsOfStepsIntoWalls) {
  InstallTightContactFilter();
  for (const std::string robot : {"p3dx", "magellan_pro"}) {
    Compiled a(robot), b(robot), c(robot);
    const mjModel* m = a.model.get();
    // c steps without placing the draw-only geoms (the robot's visual ones) and the sites, placed
    // before each comparison as Scene::data() places them.
    const std::vector<int> draw_only = DrawOnlyGeoms(m, Scene::kRobotGeomGroup);
    const int shell =
        mj_name2id(m, mjOBJ_BODY, (robot == "p3dx" ? "p3dx_shell" : "magellan_shell"));
    ASSERT_EQ(static_cast<int>(draw_only.size()), m->body_geomnum[shell]) << robot;
    for (const int g : draw_only) EXPECT_EQ(m->geom_bodyid[g], shell) << robot;
    const int left = mj_name2id(m, mjOBJ_ACTUATOR, "left_wheel_motor");
    const int right = mj_name2id(m, mjOBJ_ACTUATOR, "right_wheel_motor");
    ASSERT_GE(m->body_geomnum[0], 50);  // the office's walls are in the world body
    ASSERT_TRUE(StepCanSkipSites(m)) << robot;
    ASSERT_GE(m->nsite, 16) << robot;  // the sonar ring's transducers at least
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> wheel(-12.0, 12.0);
    int steps_touching_world = 0, steps_left_unplaced = 0, steps_sites_left_unplaced = 0;
    constexpr int kSteps = 4000;
    for (int step = 0; step < kSteps; ++step) {
      if (step % 300 == 0) {
        // Full ahead into the wall first, then turns, reverses and more full-ahead spells.
        const bool ahead = step < 1200 || step % 900 == 0;
        const double l = ahead ? 12.0 : wheel(rng), r = ahead ? 12.0 : wheel(rng);
        for (mjData* d : {a.data.get(), b.data.get(), c.data.get()}) {
          d->ctrl[left] = l;
          d->ctrl[right] = r;
        }
      }
      {
        const NearContactPairs::Active active = a.pairs->Activate(a.data.get());
        mj_step(a.model.get(), a.data.get());
      }
      {
        const NearContactPairs::Active active = b.pairs->Activate(b.data.get());
        StepWithStaticWorldGeoms(b.model.get(), b.data.get());
      }
      {
        const NearContactPairs::Active active = c.pairs->Activate(c.data.get());
        ASSERT_TRUE(StepWithStaticWorldGeoms(c.model.get(), c.data.get(), draw_only, true));
        ASSERT_EQ(c.model->nsite, m->nsite);  // restored
      }
      // Unplaced, the draw-only geoms still hold the pose of the step before.
      if (!SameBytes(c.data->geom_xpos + 3 * draw_only[0], a.data->geom_xpos + 3 * draw_only[0],
                     3)) {
        ++steps_left_unplaced;
      }
      if (!SameBytes(c.data->site_xpos, a.data->site_xpos, 3 * m->nsite)) {
        ++steps_sites_left_unplaced;
      }
      PlaceGeoms(c.model.get(), c.data.get(), draw_only);
      // One site alone (as SitePoseInWorld places it), then all of them.
      const int one = step % m->nsite;
      PlaceSite(c.model.get(), c.data.get(), one);
      ASSERT_TRUE(SameBytes(c.data->site_xpos + 3 * one, a.data->site_xpos + 3 * one, 3)) << step;
      ASSERT_TRUE(SameBytes(c.data->site_xmat + 9 * one, a.data->site_xmat + 9 * one, 9)) << step;
      PlaceSites(c.model.get(), c.data.get());
      {
        const mjData *d = b.data.get(), *dc = c.data.get();
        ASSERT_TRUE(SameBytes(d->qpos, dc->qpos, m->nq)) << robot << " step " << step;
        ASSERT_TRUE(SameBytes(d->qvel, dc->qvel, m->nv)) << robot << " step " << step;
        ASSERT_TRUE(SameBytes(d->qacc, dc->qacc, m->nv)) << robot << " step " << step;
        ASSERT_TRUE(SameBytes(d->geom_xpos, dc->geom_xpos, 3 * m->ngeom)) << robot << " " << step;
        ASSERT_TRUE(SameBytes(d->geom_xmat, dc->geom_xmat, 9 * m->ngeom)) << robot << " " << step;
        ASSERT_TRUE(SameContacts(d, dc)) << robot << " step " << step;
        ASSERT_TRUE(SameBytes(d->site_xpos, dc->site_xpos, 3 * m->nsite)) << robot << " " << step;
        ASSERT_TRUE(SameBytes(d->site_xmat, dc->site_xmat, 9 * m->nsite)) << robot << " " << step;
      }
      const mjData* da = a.data.get();
      const mjData* db = b.data.get();
      ASSERT_TRUE(SameBytes(da->qpos, db->qpos, m->nq)) << robot << " step " << step;
      ASSERT_TRUE(SameBytes(da->qvel, db->qvel, m->nv)) << robot << " step " << step;
      ASSERT_TRUE(SameBytes(da->qacc, db->qacc, m->nv)) << robot << " step " << step;
      ASSERT_TRUE(SameBytes(da->qacc_warmstart, db->qacc_warmstart, m->nv)) << robot;
      ASSERT_TRUE(SameBytes(da->geom_xpos, db->geom_xpos, 3 * m->ngeom)) << robot << " " << step;
      ASSERT_TRUE(SameBytes(da->geom_xmat, db->geom_xmat, 9 * m->ngeom)) << robot << " " << step;
      ASSERT_TRUE(SameContacts(da, db)) << robot << " step " << step;
      ASSERT_EQ(da->time, db->time);
      const auto world_wall = [&](int g) {
        return m->geom_bodyid[g] == 0 && m->geom_type[g] != mjGEOM_PLANE;
      };
      for (int c = 0; c < da->ncon; ++c) {
        if (world_wall(da->contact[c].geom1) || world_wall(da->contact[c].geom2)) {
          ++steps_touching_world;
          break;
        }
      }
    }
    std::printf("%s: %d of %d steps touch a wall, ends at %.2f %.2f\n", robot.c_str(),
                steps_touching_world, kSteps, a.data->qpos[0], a.data->qpos[1]);
    EXPECT_GT(steps_touching_world, 300) << robot << ": the robot must press into walls";
    EXPECT_GT(steps_left_unplaced, kSteps / 2) << robot << ": the step must skip them";
    EXPECT_GT(steps_sites_left_unplaced, kSteps / 2) << robot << ": and the sites";
  }
}

// A bad state resets the data (zeroing every pose): the next step must still match mj_step.
TEST(StaticGeomStepTest, MatchesMjStepAfterABadStateReset) {
  Compiled a("p3dx"), b("p3dx");
  for (mjData* d : {a.data.get(), b.data.get()}) d->qvel[0] = std::nan("");
  mj_step(a.model.get(), a.data.get());
  StepWithStaticWorldGeoms(b.model.get(), b.data.get());
  const mjModel* m = a.model.get();
  EXPECT_TRUE(SameBytes(a.data->qpos, b.data->qpos, m->nq));
  EXPECT_TRUE(SameBytes(a.data->geom_xpos, b.data->geom_xpos, 3 * m->ngeom));
  EXPECT_EQ(a.model->ngeom, b.model->ngeom);
}

// Anything in the step that reads sites keeps them placed by the step.
TEST(StaticGeomStepTest, SitesAreSkippedOnlyWhenNothingInTheStepReadsThem) {
  const std::string robot_only =
      "<mujoco><worldbody><body><freejoint/><geom size='0.1'/><site name='s'/>"
      "<body><joint name='j' axis='0 1 0'/><geom size='0.05'/></body></body></worldbody>";
  const auto compile = [&](const std::string& tail) {
    return LoadModelFromString(robot_only + tail + "</mujoco>", "sites_test.xml");
  };
  EXPECT_TRUE(StepCanSkipSites(compile("").get()));
  EXPECT_TRUE(StepCanSkipSites(compile("<actuator><velocity joint='j' kv='5'/></actuator>").get()));
  EXPECT_FALSE(
      StepCanSkipSites(compile("<sensor><framepos objtype='site' objname='s'/></sensor>").get()));
  EXPECT_FALSE(
      StepCanSkipSites(compile("<actuator><motor site='s' gear='1 0 0 0 0 0'/></actuator>").get()));
  EXPECT_FALSE(StepCanSkipSites(
      compile("<tendon><fixed><joint joint='j' coef='1'/></fixed></tendon>").get()));
  const MjModelPtr m = compile("");
  mjcb_control = [](const mjModel*, mjData*) {};
  EXPECT_FALSE(StepCanSkipSites(m.get()));
  mjcb_control = nullptr;
}

}  // namespace
}  // namespace plywood::sim
