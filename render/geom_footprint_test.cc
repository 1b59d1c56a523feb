#include "render/geom_footprint.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/world/mujoco_handles.h"

namespace plywood::render {
namespace {

constexpr char kWorld[] = R"(
<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="0 0 1"/>
    <geom name="wall" type="box" pos="1 2 0.25" euler="0 0 90" size="0.5 0.05 0.25"/>
    <body name="shelf" pos="-1 0 0" euler="0 0 90">
      <geom name="post" type="cylinder" pos="1 0 0.3" size="0.1 0.3"/>
    </body>
    <body name="ball" pos="0 0 1">
      <freejoint/>
      <geom type="sphere" size="0.1"/>
    </body>
  </worldbody>
</mujoco>)";

TEST(GeomFootprintTest, StaticPosesComposeBodiesAndMovingGeomsAreExcluded) {
  const sim::MjModelPtr m = sim::LoadModelFromString(kWorld, "world.xml");
  const int wall = mj_name2id(m.get(), mjOBJ_GEOM, "wall");
  const int post = mj_name2id(m.get(), mjOBJ_GEOM, "post");
  EXPECT_TRUE(IsStaticGeom(m.get(), wall));
  EXPECT_TRUE(IsStaticGeom(m.get(), post));
  EXPECT_FALSE(IsStaticGeom(m.get(), m->ngeom - 1));
  // The shelf body turns its local +x into world +y: the post lands at (-1, 1).
  const Eigen::Vector3d p = StaticGeomPose(m.get(), post).translation();
  EXPECT_NEAR(p.x(), -1.0, 1e-9);
  EXPECT_NEAR(p.y(), 1.0, 1e-9);
  EXPECT_NEAR(p.z(), 0.3, 1e-9);
}

// A mocap body and a body on it have body_weldid 0, as a static body has, yet mocap_pos moves
// them: the software picture drew them where the model put them, wherever they were.
TEST(GeomFootprintTest, AMocapBodyAndWhatHangsOnItAreNotStatic) {
  const sim::MjModelPtr m = sim::LoadModelFromString(R"(
<mujoco>
  <worldbody>
    <geom name="wall" type="box" pos="1 2 0.25" size="0.5 0.05 0.25"/>
    <body name="marker" mocap="true" pos="0 0 0.1">
      <geom name="mark" type="box" size="0.1 0.1 0.1"/>
      <body name="flag" pos="0.3 0 0"><geom name="pole" type="sphere" size="0.05"/></body>
    </body>
  </worldbody>
</mujoco>)",
                                                     "world.xml");
  EXPECT_TRUE(IsStaticGeom(m.get(), mj_name2id(m.get(), mjOBJ_GEOM, "wall")));
  EXPECT_FALSE(IsStaticGeom(m.get(), mj_name2id(m.get(), mjOBJ_GEOM, "mark")));
  EXPECT_FALSE(IsStaticGeom(m.get(), mj_name2id(m.get(), mjOBJ_GEOM, "pole")));
  // So the static extent is the wall's alone.
  EXPECT_NEAR(StaticGeometryExtent(m.get()).bounds.x_min_m, 0.5, 1e-9);
}

TEST(GeomFootprintTest, ExtentCoversRotatedBoxAndCylinderButNotFloorOrBall) {
  const sim::MjModelPtr m = sim::LoadModelFromString(kWorld, "world.xml");
  const StaticExtent extent = StaticGeometryExtent(m.get());
  // Wall turned 90 deg: 0.1 m wide in x, 1 m long in y, centred at (1, 2).
  EXPECT_NEAR(extent.bounds.x_max_m, 1.05, 1e-9);
  EXPECT_NEAR(extent.bounds.y_max_m, 2.5, 1e-9);
  EXPECT_NEAR(extent.bounds.y_min_m, 0.9, 1e-9);  // post at y = 1 with radius 0.1
  EXPECT_NEAR(extent.bounds.x_min_m, -1.1, 1e-9);
  EXPECT_NEAR(extent.z_max_m, 0.6, 1e-9);
}

TEST(GeomFootprintTest, BoxFootprintIsItsRotatedRectangle) {
  const sim::MjModelPtr m = sim::LoadModelFromString(kWorld, "world.xml");
  const int wall = mj_name2id(m.get(), mjOBJ_GEOM, "wall");
  const GeomFootprint f = FootprintOf(m.get(), wall, StaticGeomPose(m.get(), wall));
  ASSERT_EQ(f.outline_W.size(), 4u);
  double area = 0.0;  // shoelace; positive for counter-clockwise
  for (std::size_t i = 0; i < 4; ++i) {
    const Eigen::Vector2d& a = f.outline_W[i];
    const Eigen::Vector2d& b = f.outline_W[(i + 1) % 4];
    area += 0.5 * (a.x() * b.y() - b.x() * a.y());
  }
  EXPECT_NEAR(area, 1.0 * 0.1, 1e-9);
  EXPECT_NEAR(f.z_top_m, 0.5, 1e-9);
}

TEST(GeomFootprintTest, WorldWithOnlyAFloorFallsBackToItsSize) {
  const sim::MjModelPtr m = sim::LoadModelFromString(
      "<mujoco><worldbody><geom type='plane' pos='1 0 0' size='2 3 0.1'/></worldbody></mujoco>",
      "floor.xml");
  const StaticExtent extent = StaticGeometryExtent(m.get());
  EXPECT_NEAR(extent.bounds.x_min_m, -1.0, 1e-9);
  EXPECT_NEAR(extent.bounds.x_max_m, 3.0, 1e-9);
  EXPECT_NEAR(extent.bounds.y_max_m, 3.0, 1e-9);
}

}  // namespace
}  // namespace plywood::render
