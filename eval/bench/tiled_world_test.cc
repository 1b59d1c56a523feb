#include "eval/bench/tiled_world.h"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "tests/support/mujoco_test_support.h"

namespace plywood::eval {
namespace {

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;

ModelPtr Load(const std::filesystem::path& path) {
  char error[1000] = "";
  ModelPtr model(mj_loadXML(path.c_str(), nullptr, error, sizeof(error)));
  EXPECT_TRUE(model) << error;
  return model;
}

TEST(TiledWorldTest, NineOfficesAroundTheOriginalWithOneFloor) {
  const std::filesystem::path office = testing::SourceRoot() / "worlds" / "office.xml";
  const std::filesystem::path tiled = testing::MakeTempDir("tiled_world") / "office_3x3.xml";
  std::ofstream(tiled) << TiledWorldMjcf(office, 3, 3, 17.0, 11.0);
  const ModelPtr one = Load(office);
  const ModelPtr nine = Load(tiled);
  ASSERT_TRUE(one && nine);
  // Every geom but the floor, nine times; one floor.
  EXPECT_EQ(nine->ngeom, 1 + 9 * (one->ngeom - 1));
  EXPECT_EQ(nine->nbody, one->nbody);  // still all in the worldbody: static
  const int wall = mj_name2id(one.get(), mjOBJ_GEOM, "wall_1");
  ASSERT_GE(wall, 0);
  const auto pos_of = [&](const char* name) {
    const int id = mj_name2id(nine.get(), mjOBJ_GEOM, name);
    EXPECT_GE(id, 0) << name;
    return id < 0 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(nine->geom_pos + 3 * id);
  };
  const Eigen::Vector3d original(one->geom_pos + 3 * wall);
  EXPECT_TRUE(pos_of("wall_1_t1_1").isApprox(original));  // the centre tile is the original
  EXPECT_TRUE(pos_of("wall_1_t0_0").isApprox(original + Eigen::Vector3d(-17.0, -11.0, 0.0)));
  EXPECT_TRUE(pos_of("wall_1_t2_1").isApprox(original + Eigen::Vector3d(17.0, 0.0, 0.0)));
  const int floor = mj_name2id(nine.get(), mjOBJ_GEOM, "floor");
  ASSERT_GE(floor, 0);
  EXPECT_DOUBLE_EQ(nine->geom_size[3 * floor], 8.5 + 17.0);
  EXPECT_DOUBLE_EQ(nine->geom_size[3 * floor + 1], 5.5 + 11.0);
}

TEST(TiledWorldTest, AWorldWithoutFloorIsRefused) {
  const std::filesystem::path world = testing::MakeTempDir("tiled_world_bad") / "w.xml";
  std::ofstream(world) << "<mujoco><worldbody>\n<geom name=\"a\" type=\"box\" pos=\"0 0 0\" "
                          "size=\"1 1 1\"/>\n</worldbody></mujoco>\n";
  EXPECT_THROW(TiledWorldMjcf(world, 3, 3, 1.0, 1.0), std::runtime_error);
  EXPECT_THROW(TiledWorldMjcf(world.parent_path() / "missing.xml", 3, 3, 1.0, 1.0),
               std::runtime_error);
}

}  // namespace
}  // namespace plywood::eval
