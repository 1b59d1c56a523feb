#include "sim/mujoco_ray_caster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sim/mujoco_handles.h"
#include "sim/scene.h"

namespace plywood::sim {
namespace {

// A floor, a wall at x = 3, a yawed box, a cylinder, a table whose top is above laser height, a
// "robot" (free body, geom group 3) standing in front of the wall, geoms in groups 4 and 5 and a
// fully transparent one.
constexpr char kWorld[] = R"(
<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="0 0 1"/>
    <geom name="wall" type="box" pos="3 0 1" size="0.05 2 1"/>
    <geom name="yawed" type="box" pos="0 -4 0.5" euler="0 0 30" size="0.5 0.25 0.5"/>
    <geom name="post" type="cylinder" pos="-3 1 0.5" size="0.25 0.5"/>
    <geom name="table_top" type="box" pos="0 4 0.72" size="0.6 0.4 0.02"/>
    <geom name="group4" type="box" group="4" pos="-2 -2 0.5" size="0.1 0.1 0.5"/>
    <geom name="group5" type="box" group="5" pos="2 -2 0.5" size="0.1 0.1 0.5"/>
    <geom name="glass" type="box" rgba="1 1 1 0" pos="-2 2 0.5" size="0.1 0.1 0.5"/>
    <body name="robot" pos="1.5 0 0">
      <freejoint/>
      <geom name="robot_chassis" type="box" group="3" pos="0 0 0.3" size="0.2 0.2 0.2"/>
    </body>
  </worldbody>
</mujoco>)";

class MujocoRayCasterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    model_ = LoadModelFromString(kWorld, std::string(PLYWOOD_BINARY_DIR) + "/mujoco_ray.xml");
    data_.reset(mj_makeData(model_.get()));
    mj_forward(model_.get(), data_.get());
  }
  int Geom(const char* name) const { return mj_name2id(model_.get(), mjOBJ_GEOM, name); }

  MjModelPtr model_;
  MjDataPtr data_;
};

void ExpectNormal(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected) {
  EXPECT_NEAR((actual - expected).norm(), 0.0, 1e-12)
      << actual.transpose() << " vs " << expected.transpose();
}

TEST_F(MujocoRayCasterTest, WallAtKnownDistanceThroughTheRobot) {
  const MujocoRayCaster caster(model_.get(), data_.get());
  RayHit hit;
  // The robot's chassis (group 3) stands between the origin and the wall and is not seen.
  ASSERT_TRUE(caster.Cast({0, 0, 0.3}, {1, 0, 0}, 8.0, &hit));
  EXPECT_NEAR(hit.distance_m, 2.95, 1e-12);
  EXPECT_EQ(hit.geom_id, Geom("wall"));
  ExpectNormal(hit.normal_W, {-1, 0, 0});
}

TEST_F(MujocoRayCasterTest, MaxRangeAndMiss) {
  const MujocoRayCaster caster(model_.get(), data_.get());
  RayHit hit;
  EXPECT_FALSE(caster.Cast({0, 0, 0.3}, {1, 0, 0}, 2.9, &hit));
  EXPECT_TRUE(caster.Cast({0, 0, 0.3}, {1, 0, 0}, 2.96, &hit));
  EXPECT_FALSE(caster.Cast({0, 0, 0.3}, {-1, 0, 0}, 100.0, &hit));  // nothing there
  EXPECT_FALSE(caster.Cast({0, 0, 0.3}, {0, 0, 1}, 100.0, &hit));   // the sky
}

TEST_F(MujocoRayCasterTest, FloorFromAbove) {
  const MujocoRayCaster caster(model_.get(), data_.get());
  RayHit hit;
  const Eigen::Vector3d dir = Eigen::Vector3d(-1, 0, -1).normalized();
  ASSERT_TRUE(caster.Cast({0, 0, 0.3}, dir, 8.0, &hit));
  EXPECT_NEAR(hit.distance_m, 0.3 * std::sqrt(2.0), 1e-12);
  EXPECT_EQ(hit.geom_id, Geom("floor"));
  ExpectNormal(hit.normal_W, {0, 0, 1});
}

TEST_F(MujocoRayCasterTest, YawedBoxObliqueRay) {
  const MujocoRayCaster caster(model_.get(), data_.get());
  const double yaw = M_PI / 6;
  const Eigen::Vector3d u(std::cos(yaw), std::sin(yaw), 0), w(-std::sin(yaw), std::cos(yaw), 0);
  // Aim at a point on the +u face, from 2 m out along the normal and 0.7 m sideways.
  const Eigen::Vector3d target = Eigen::Vector3d(0, -4, 0.3) + 0.5 * u + 0.1 * w;
  const Eigen::Vector3d origin = target + 2.0 * u + 0.7 * w;
  const Eigen::Vector3d dir = (target - origin).normalized();
  RayHit hit;
  ASSERT_TRUE(caster.Cast(origin, dir, 8.0, &hit));
  EXPECT_NEAR(hit.distance_m, std::hypot(2.0, 0.7), 1e-12);
  EXPECT_EQ(hit.geom_id, Geom("yawed"));
  ExpectNormal(hit.normal_W, u);
}

TEST_F(MujocoRayCasterTest, CylinderOffAxis) {
  const MujocoRayCaster caster(model_.get(), data_.get());
  RayHit hit;
  ASSERT_TRUE(caster.Cast({-1, 1.1, 0.3}, {-1, 0, 0}, 8.0, &hit));
  const double depth = std::sqrt(0.25 * 0.25 - 0.1 * 0.1);
  EXPECT_NEAR(hit.distance_m, 2.0 - depth, 1e-12);
  EXPECT_EQ(hit.geom_id, Geom("post"));
  ExpectNormal(hit.normal_W, Eigen::Vector3d(depth, 0.1, 0) / 0.25);
}

TEST_F(MujocoRayCasterTest, TableTopOnlyAtItsHeight) {
  const MujocoRayCaster caster(model_.get(), data_.get());
  RayHit hit;
  EXPECT_FALSE(caster.Cast({0, 2, 0.3}, {0, 1, 0}, 8.0, &hit));
  ASSERT_TRUE(caster.Cast({0, 2, 0.72}, {0, 1, 0}, 8.0, &hit));
  EXPECT_NEAR(hit.distance_m, 1.6, 1e-12);
  EXPECT_EQ(hit.geom_id, Geom("table_top"));
  ExpectNormal(hit.normal_W, {0, -1, 0});
}

TEST_F(MujocoRayCasterTest, GroupsFourAndFiveSeenTransparentSkipped) {
  const MujocoRayCaster caster(model_.get(), data_.get());
  RayHit hit;
  ASSERT_TRUE(caster.Cast({-2, 0, 0.3}, {0, -1, 0}, 8.0, &hit));
  EXPECT_EQ(hit.geom_id, Geom("group4"));
  ASSERT_TRUE(caster.Cast({2, 0, 0.3}, {0, -1, 0}, 8.0, &hit));
  EXPECT_EQ(hit.geom_id, Geom("group5"));
  EXPECT_FALSE(caster.Cast({-2, 0, 0.3}, {0, 1, 0}, 8.0, &hit));  // the glass
  EXPECT_FALSE(IsRayVisibleGeom(model_.get(), Geom("glass")));
  EXPECT_FALSE(IsRayVisibleGeom(model_.get(), Geom("robot_chassis")));
  EXPECT_TRUE(IsRayVisibleGeom(model_.get(), Geom("group5")));
  EXPECT_EQ(RayGeomGroups()[Scene::kRobotGeomGroup], 0);
}

}  // namespace
}  // namespace plywood::sim
