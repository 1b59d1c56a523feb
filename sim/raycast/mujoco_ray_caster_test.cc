#include "sim/raycast/mujoco_ray_caster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sim/world/mujoco_handles.h"
#include "sim/world/scene.h"
#include "tests/support/ray_caster_test_support.h"

namespace plywood::sim {
namespace {

using plywood::testing::ClosedFormWorld;
using plywood::testing::CompiledWorld;
using plywood::testing::CompileWorld;
using plywood::testing::ExpectNormal;

// The closed-form world plus geoms in groups 4 and 5 and a fully transparent one.
constexpr char kExtraGeoms[] =
    R"(    <geom name="group4" type="box" group="4" pos="-2 -2 0.5" size="0.1 0.1 0.5"/>
    <geom name="group5" type="box" group="5" pos="2 -2 0.5" size="0.1 0.1 0.5"/>
    <geom name="glass" type="box" rgba="1 1 1 0" pos="-2 2 0.5" size="0.1 0.1 0.5"/>
)";

class MujocoRayCasterTest : public ::testing::Test {
 protected:
  void SetUp() override { world_ = CompileWorld(ClosedFormWorld(kExtraGeoms), "mujoco_ray.xml"); }
  int Geom(const char* name) const { return world_.Geom(name); }

  CompiledWorld world_;
};

TEST_F(MujocoRayCasterTest, WallAtKnownDistanceThroughTheRobot) {
  const MujocoRayCaster caster(world_.model.get(), world_.data.get());
  RayHit hit;
  // The robot's chassis (group 3) stands between the origin and the wall and is not seen.
  ASSERT_TRUE(caster.Cast({0, 0, 0.3}, {1, 0, 0}, 8.0, &hit));
  EXPECT_NEAR(hit.distance_m, 2.95, 1e-12);
  EXPECT_EQ(hit.geom_id, Geom("wall"));
  ExpectNormal(hit.normal_W, {-1, 0, 0});
}

TEST_F(MujocoRayCasterTest, MaxRangeAndMiss) {
  const MujocoRayCaster caster(world_.model.get(), world_.data.get());
  RayHit hit;
  EXPECT_FALSE(caster.Cast({0, 0, 0.3}, {1, 0, 0}, 2.9, &hit));
  EXPECT_TRUE(caster.Cast({0, 0, 0.3}, {1, 0, 0}, 2.96, &hit));
  EXPECT_FALSE(caster.Cast({0, 0, 0.3}, {-1, 0, 0}, 100.0, &hit));  // nothing there
  EXPECT_FALSE(caster.Cast({0, 0, 0.3}, {0, 0, 1}, 100.0, &hit));   // the sky
}

TEST_F(MujocoRayCasterTest, FloorFromAbove) {
  const MujocoRayCaster caster(world_.model.get(), world_.data.get());
  RayHit hit;
  const Eigen::Vector3d dir = Eigen::Vector3d(-1, 0, -1).normalized();
  ASSERT_TRUE(caster.Cast({0, 0, 0.3}, dir, 8.0, &hit));
  EXPECT_NEAR(hit.distance_m, 0.3 * std::sqrt(2.0), 1e-12);
  EXPECT_EQ(hit.geom_id, Geom("floor"));
  ExpectNormal(hit.normal_W, {0, 0, 1});
}

TEST_F(MujocoRayCasterTest, YawedBoxObliqueRay) {
  const MujocoRayCaster caster(world_.model.get(), world_.data.get());
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
  const MujocoRayCaster caster(world_.model.get(), world_.data.get());
  RayHit hit;
  ASSERT_TRUE(caster.Cast({-1, 1.1, 0.3}, {-1, 0, 0}, 8.0, &hit));
  const double depth = std::sqrt(0.25 * 0.25 - 0.1 * 0.1);
  EXPECT_NEAR(hit.distance_m, 2.0 - depth, 1e-12);
  EXPECT_EQ(hit.geom_id, Geom("post"));
  ExpectNormal(hit.normal_W, Eigen::Vector3d(depth, 0.1, 0) / 0.25);
}

TEST_F(MujocoRayCasterTest, TableTopOnlyAtItsHeight) {
  const MujocoRayCaster caster(world_.model.get(), world_.data.get());
  RayHit hit;
  EXPECT_FALSE(caster.Cast({0, 2, 0.3}, {0, 1, 0}, 8.0, &hit));
  ASSERT_TRUE(caster.Cast({0, 2, 0.72}, {0, 1, 0}, 8.0, &hit));
  EXPECT_NEAR(hit.distance_m, 1.6, 1e-12);
  EXPECT_EQ(hit.geom_id, Geom("table_top"));
  ExpectNormal(hit.normal_W, {0, -1, 0});
}

TEST_F(MujocoRayCasterTest, GroupsFourAndFiveSeenTransparentSkipped) {
  const MujocoRayCaster caster(world_.model.get(), world_.data.get());
  RayHit hit;
  ASSERT_TRUE(caster.Cast({-2, 0, 0.3}, {0, -1, 0}, 8.0, &hit));
  EXPECT_EQ(hit.geom_id, Geom("group4"));
  ASSERT_TRUE(caster.Cast({2, 0, 0.3}, {0, -1, 0}, 8.0, &hit));
  EXPECT_EQ(hit.geom_id, Geom("group5"));
  EXPECT_FALSE(caster.Cast({-2, 0, 0.3}, {0, 1, 0}, 8.0, &hit));  // the glass
  EXPECT_FALSE(IsRayVisibleGeom(world_.model.get(), Geom("glass")));
  EXPECT_FALSE(IsRayVisibleGeom(world_.model.get(), Geom("robot_chassis")));
  EXPECT_TRUE(IsRayVisibleGeom(world_.model.get(), Geom("group5")));
  EXPECT_EQ(RayGeomGroups()[Scene::kRobotGeomGroup], 0);
}

}  // namespace
}  // namespace plywood::sim
