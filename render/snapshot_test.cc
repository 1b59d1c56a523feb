#include "render/snapshot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render/image_ops.h"
#include "render/offscreen_context.h"
#include "render/png_image.h"
#include "sim/world/mujoco_handles.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::render {
namespace {

// A 4 m x 3 m plywood room with a pillar, and the P3-DX at (-1, -0.5) facing +y.
std::string RoomWithRobotMjcf() {
  return R"(
<mujoco>
  <include file=")" +
         (testing::SourceRoot() / "models" / "p3dx.xml").string() + R"("/>
  <worldbody>
    <light pos="0 0 3" dir="0 0 -1" directional="true" diffuse="0.3 0.3 0.3"/>
    <geom name="floor" type="plane" size="0 0 1" rgba="0.55 0.55 0.52 1"/>
    <geom type="box" pos="0 1.5 0.3" size="2 0.01 0.3" rgba="0.8 0.65 0.45 1"/>
    <geom type="box" pos="0 -1.5 0.3" size="2 0.01 0.3" rgba="0.8 0.65 0.45 1"/>
    <geom type="box" pos="2 0 0.3" size="0.01 1.5 0.3" rgba="0.8 0.65 0.45 1"/>
    <geom type="box" pos="-2 0 0.3" size="0.01 1.5 0.3" rgba="0.8 0.65 0.45 1"/>
    <geom type="cylinder" pos="0.8 0.4 0.3" size="0.15 0.3" rgba="0.3 0.5 0.7 1"/>
  </worldbody>
</mujoco>)";
}

const Eigen::Vector2d kRobot_W(-1.0, -0.5);

struct Fixture {
  sim::MjModelPtr m;
  sim::MjDataPtr d;
};

Fixture MakeRoom() {
  Fixture f;
  f.m = sim::LoadModelFromString(RoomWithRobotMjcf(), "room.xml");
  f.d.reset(mj_makeData(f.m.get()));
  // Free joint qpos: x y z, then quaternion; yaw 90 deg.
  f.d->qpos[0] = kRobot_W.x();
  f.d->qpos[1] = kRobot_W.y();
  f.d->qpos[3] = std::cos(std::numbers::pi / 4);
  f.d->qpos[6] = std::sin(std::numbers::pi / 4);
  mj_forward(f.m.get(), f.d.get());
  return f;
}

std::vector<PathOverlay> Paths() {
  PathOverlay truth{"ground truth", {}, colours::kBlack, 3.0};
  PathOverlay estimate{"encoders", {}, colours::kRed, 2.0};
  for (int i = 0; i <= 40; ++i) {
    const double t = i / 40.0;
    truth.points_W.push_back({-1.0 + 2.0 * t, -0.5 + 1.5 * t * t});
    estimate.points_W.push_back({-1.0 + 2.1 * t, -0.5 + 1.3 * t * t});
  }
  return {truth, estimate};
}

bool IsBlack(Rgb c) { return c.r < 40 && c.g < 40 && c.b < 40; }

void ExpectPathDrawn(const Snapshot& s, const PathOverlay& path) {
  // Interior path points (away from the other path's crossing near the start) are painted.
  for (std::size_t i = 10; i < path.points_W.size(); i += 10) {
    const Eigen::Vector2d uv = s.picture.world_to_pixel.ToPixel(path.points_W[i]);
    EXPECT_TRUE(
        IsBlack(PixelAt(s.picture.image, static_cast<int>(uv.x()), static_cast<int>(uv.y()))))
        << i;
  }
}

TEST(SnapshotTest, SoftwareSnapshotHasPathsLegendAndRobot) {
  Fixture f = MakeRoom();
  SnapshotOptions options;
  options.use_opengl = false;
  const std::vector<PathOverlay> paths = Paths();
  const Snapshot s = RenderSnapshot(f.m.get(), f.d.get(), paths, options);
  EXPECT_EQ(s.backend, SnapshotBackend::kSoftware);
  // Walls span 4.02 m x 3.02 m, plus 0.25 m margins: 1024 px along x.
  EXPECT_EQ(s.picture.image.width, 1024);
  EXPECT_NEAR(s.picture.world_to_pixel.pixels_per_m, 1024 / 4.52, 1e-9);
  ExpectPathDrawn(s, paths[0]);
  // The laser housing (blue, 0.156 m square 21 mm ahead of the centre of rotation) shows 6 cm
  // ahead of the robot, i.e. at +y because the robot faces +y (the path's start dot hides the
  // centre itself).
  const Eigen::Vector2d laser_uv =
      s.picture.world_to_pixel.ToPixel(kRobot_W + Eigen::Vector2d(0, 0.06));
  const Rgb laser =
      PixelAt(s.picture.image, static_cast<int>(laser_uv.x()), static_cast<int>(laser_uv.y()));
  EXPECT_GT(laser.b, laser.r + 40);
}

TEST(SnapshotTest, WriteSnapshotWritesAReadablePngEvenWithoutOpenGl) {
  Fixture f = MakeRoom();
  const std::filesystem::path dir = testing::MakeTempDir("snapshot_software");
  SnapshotOptions options;
  options.use_opengl = false;
  options.view.longer_side_px = 300;
  EXPECT_EQ(WriteSnapshot(f.m.get(), f.d.get(), Paths(), dir / "snapshot.png", options),
            SnapshotBackend::kSoftware);
  const RgbImage image = ReadPng(dir / "snapshot.png");
  EXPECT_EQ(image.width, 300);
  EXPECT_GT(image.height, 150);
}

TEST(SnapshotTest, OpenGlSnapshotShowsRobotWallsAndPaths) {
  if (!OffscreenRenderingAvailable()) GTEST_SKIP() << "no offscreen OpenGL context here";
  Fixture f = MakeRoom();
  const std::vector<PathOverlay> paths = Paths();
  const Snapshot s = RenderSnapshot(f.m.get(), f.d.get(), paths, {});
  ASSERT_EQ(s.backend, SnapshotBackend::kOpenGl);
  ExpectPathDrawn(s, paths[0]);
  const WorldToPixel& map = s.picture.world_to_pixel;
  const auto at = [&](const Eigen::Vector2d& p_W) {
    const Eigen::Vector2d uv = map.ToPixel(p_W);
    return PixelAt(s.picture.image, static_cast<int>(uv.x()), static_cast<int>(uv.y()));
  };
  // Laser housing (blue) ahead of the centre; the red shell's rim on the robot's right (world +x)
  // outside the top plate (|y| 0.17 .. 0.19 m).
  const Rgb laser = at(kRobot_W + Eigen::Vector2d(0, 0.06));
  EXPECT_GT(laser.b, laser.r + 30);
  const Rgb shell = at(kRobot_W + Eigen::Vector2d(0.18, -0.045));
  EXPECT_GT(shell.r, shell.g + 60);
  // A wall's top is plywood-coloured and brighter than the floor next to it.
  const Rgb wall = at({0.5, 1.5});
  const Rgb floor = at({0.5, 1.2});
  EXPECT_GT(wall.r, wall.b + 40);
  EXPECT_GT(wall.r, floor.r);
  EXPECT_GT(floor.r, 60);  // lit, not black

  const std::filesystem::path dir = testing::MakeTempDir("snapshot_opengl");
  EXPECT_EQ(WriteSnapshot(f.m.get(), f.d.get(), paths, dir / "snapshot.png"),
            SnapshotBackend::kOpenGl);
  EXPECT_EQ(ReadPng(dir / "snapshot.png").pixels.size(), s.picture.image.pixels.size());
}

// A plug-in estimator whose path reaches 1e300 m: the GL camera (floats) became infinite and the
// floor map NaN, and the scale bar cast NaN to int (UBSan: "-nan is outside the range of
// representable values of type 'int'"). Such a frame is drawn in software, its map finite.
TEST(SnapshotTest, APathAtTheEdgeOfDoublesIsFramedInSoftwareWithAFiniteMap) {
  Fixture f = MakeRoom();
  std::vector<PathOverlay> paths = Paths();
  paths[1].points_W.push_back({1e300, 0.0});
  const Snapshot s = RenderSnapshot(f.m.get(), f.d.get(), paths, {});
  EXPECT_EQ(s.backend, SnapshotBackend::kSoftware);
  const WorldToPixel& map = s.picture.world_to_pixel;
  EXPECT_TRUE(std::isfinite(map.pixels_per_m) && map.pixels_per_m > 0) << map.pixels_per_m;
  EXPECT_TRUE(std::isfinite(map.x_left_m)) << map.x_left_m;
  EXPECT_TRUE(std::isfinite(map.y_top_m)) << map.y_top_m;
}

TEST(SnapshotOptionsTest, ValidateNamesNestedAndOwnFields) {
  SnapshotOptions options;
  options.view.longer_side_px = 3;
  try {
    options.Validate();
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("view.longer_side_px:", 0), 0u) << e.what();
  }
  options = {};
  options.legend_text_scale = 0;
  try {
    options.Validate();
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("legend_text_scale:", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace plywood::render
