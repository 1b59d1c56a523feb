#include "tests/support/ray_caster_test_support.h"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "plywood_paths.h"

namespace plywood::testing {

int CompiledWorld::Geom(const char* name) const {
  return mj_name2id(model.get(), mjOBJ_GEOM, name);
}

CompiledWorld CompileWorld(const std::string& mjcf, const std::string& file_name) {
  CompiledWorld world;
  world.model = sim::LoadModelFromString(mjcf, std::string(PLYWOOD_BINARY_DIR) + "/" + file_name);
  world.data.reset(mj_makeData(world.model.get()));
  mj_forward(world.model.get(), world.data.get());
  return world;
}

std::string ClosedFormWorld(const std::string& extra_geoms) {
  return R"(
<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="0 0 1"/>
    <geom name="wall" type="box" pos="3 0 1" size="0.05 2 1"/>
    <geom name="yawed" type="box" pos="0 -4 0.5" euler="0 0 30" size="0.5 0.25 0.5"/>
    <geom name="post" type="cylinder" pos="-3 1 0.5" size="0.25 0.5"/>
    <geom name="table_top" type="box" pos="0 4 0.72" size="0.6 0.4 0.02"/>
)" + extra_geoms +
         R"(    <body name="robot" pos="1.5 0 0">
      <freejoint/>
      <geom name="robot_chassis" type="box" group="3" pos="0 0 0.3" size="0.2 0.2 0.2"/>
    </body>
  </worldbody>
</mujoco>)";
}

void ExpectNormal(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected) {
  EXPECT_NEAR((actual - expected).norm(), 0.0, 1e-12)
      << actual.transpose() << " vs " << expected.transpose();
}

}  // namespace plywood::testing
