#include "render/async_snapshot_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>
#include <stdexcept>
#include <string>
#include <thread>

#include "render/offscreen_context.h"
#include "sim/world/mujoco_handles.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::render {
namespace {

// A 4 m x 3 m room and the P3-DX, which the test moves after the writer has copied the model.
std::string RoomWithRobotMjcf() {
  return R"(
<mujoco>
  <include file=")" +
         (testing::SourceRoot() / "models" / "p3dx.xml").string() + R"("/>
  <worldbody>
    <light pos="0 0 3" dir="0 0 -1" directional="true" diffuse="0.3 0.3 0.3"/>
    <geom name="floor" type="plane" size="0 0 1" rgba="0.55 0.55 0.52 1"/>
    <geom type="box" pos="0 1.5 0.3" size="2 0.01 0.3" rgba="0.8 0.65 0.45 1"/>
    <geom type="box" pos="2 0 0.3" size="0.01 1.5 0.3" rgba="0.8 0.65 0.45 1"/>
    <geom type="cylinder" pos="0.8 0.4 0.3" size="0.15 0.3" rgba="0.3 0.5 0.7 1"/>
  </worldbody>
</mujoco>)";
}

std::string FileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A path leaving the room to the south-west: the final framing is not the static one the
// writer's renderer was made with, but its picture fits the renderer's buffers (reframed).
std::vector<PathOverlay> PathsBeyondTheRoom() {
  PathOverlay truth{"ground truth", {}, colours::kBlack, 3.0};
  for (int i = 0; i <= 20; ++i) truth.points_W.push_back({-1.0 - 0.15 * i, -0.5 - 0.1 * i});
  return {truth};
}

// A path far to the south: the picture turns taller than the buffers (a new renderer).
std::vector<PathOverlay> PathsFarSouth() {
  PathOverlay truth{"ground truth", {}, colours::kBlack, 3.0};
  for (int i = 0; i <= 20; ++i) truth.points_W.push_back({-1.0, -0.5 - 0.3 * i});
  return {truth};
}

// A path inside the room: the final framing is the static one, so the writer draws its final
// frame over the static frame it kept during the run.
std::vector<PathOverlay> PathsInTheRoom() {
  PathOverlay truth{"ground truth", {}, colours::kBlack, 3.0};
  for (int i = 0; i <= 20; ++i) truth.points_W.push_back({0.5 - 0.075 * i, 0.2 - 0.035 * i});
  return {truth};
}

class AsyncSnapshotWriterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    m_ = sim::LoadModelFromString(RoomWithRobotMjcf(), "room.xml");
    d_.reset(mj_makeData(m_.get()));
    mj_forward(m_.get(), d_.get());
    dir_ = testing::MakeTempDir("async_snapshot");
    options_.view.longer_side_px = 240;
  }
  // The state pictured: the robot moved and turned, as at the end of a run.
  void MoveRobot() {
    d_->qpos[0] = -1.0;
    d_->qpos[1] = -0.5;
    d_->qpos[3] = std::cos(std::numbers::pi / 8);
    d_->qpos[6] = std::sin(std::numbers::pi / 8);
    mj_forward(m_.get(), d_.get());
  }
  // The same picture through WriteSnapshot, and the writer's, as file bytes.
  // With `into_ready_data`, Write is called once the thread's mjData for it is ready (as at the
  // end of a run), else at once (usually before).
  void ExpectSameBytesAsWriteSnapshot(const std::vector<PathOverlay>& paths,
                                      bool into_ready_data = false) {
    AsyncSnapshotWriter writer(m_.get(), options_);
    MoveRobot();
    if (into_ready_data) {
      // Not a timing assertion: waits for the thread's first step, however long it takes.
      while (!writer.HandOverDataReady()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    writer.Write(d_.get(), paths, dir_ / "async.png");
    if (into_ready_data) {
      EXPECT_FALSE(writer.HandOverDataReady());  // taken by Write
    }
    const mjtNum x = d_->qpos[0];
    d_->qpos[0] = 5.0;  // Write copied the state: changing it now must not show
    mj_forward(m_.get(), d_.get());
    const SnapshotBackend backend = writer.Finish();
    d_->qpos[0] = x;
    mj_forward(m_.get(), d_.get());
    EXPECT_EQ(WriteSnapshot(m_.get(), d_.get(), paths, dir_ / "sync.png", options_), backend);
    const std::string bytes = FileBytes(dir_ / "async.png");
    EXPECT_GT(bytes.size(), 1000u);
    EXPECT_TRUE(bytes == FileBytes(dir_ / "sync.png"));
  }

  sim::MjModelPtr m_;
  sim::MjDataPtr d_;
  std::filesystem::path dir_;
  SnapshotOptions options_;
};

TEST_F(AsyncSnapshotWriterTest, OpenGlPngIsByteIdenticalToWriteSnapshot) {
  if (!OffscreenRenderingAvailable()) GTEST_SKIP() << "no offscreen OpenGL context here";
  ExpectSameBytesAsWriteSnapshot(PathsBeyondTheRoom());
  ExpectSameBytesAsWriteSnapshot(PathsFarSouth());
}

// Over the static frame only the box round the robot is drawn anew, through a frustum cut to it:
// the picture is WriteSnapshot's up to an edge pixel within the robot's reach whose samples round
// differently (docs/performance.md, "Stop 67").
TEST_F(AsyncSnapshotWriterTest, OpenGlPngOverTheStaticFrameIsWriteSnapshotsUpToTheRobotsEdge) {
  if (!OffscreenRenderingAvailable()) GTEST_SKIP() << "no offscreen OpenGL context here";
  AsyncSnapshotWriter writer(m_.get(), options_);
  MoveRobot();
  writer.Write(d_.get(), PathsInTheRoom(), dir_ / "async.png");
  ASSERT_EQ(writer.Finish(), SnapshotBackend::kOpenGl);
  const Snapshot sync = RenderSnapshot(m_.get(), d_.get(), PathsInTheRoom(), options_);
  const RgbImage async = ReadPng(dir_ / "async.png");
  ASSERT_EQ(async.width, sync.picture.image.width);
  ASSERT_EQ(async.height, sync.picture.image.height);
  // The P3-DX's footprint reaches ~0.3 m from its origin (the robot at (-1, -0.5)).
  const Eigen::Vector2d robot_px = sync.picture.world_to_pixel.ToPixel({-1.0, -0.5});
  const double reach_px = 0.35 * sync.picture.world_to_pixel.pixels_per_m + 3.0;
  int differ = 0, differ_beyond = 0;
  for (int y = 0; y < async.height; ++y) {
    for (int x = 0; x < async.width; ++x) {
      if (std::equal(async.At(x, y), async.At(x, y) + 3, sync.picture.image.At(x, y))) continue;
      ++differ;
      if ((Eigen::Vector2d(x + 0.5, y + 0.5) - robot_px).norm() > reach_px) ++differ_beyond;
    }
  }
  EXPECT_EQ(differ_beyond, 0);
  EXPECT_LE(differ, 4);
}

TEST_F(AsyncSnapshotWriterTest, WriteIntoTheThreadsReadyDataGivesTheSameBytes) {
  if (!OffscreenRenderingAvailable()) GTEST_SKIP() << "no offscreen OpenGL context here";
  ExpectSameBytesAsWriteSnapshot(PathsBeyondTheRoom(), true);
  ExpectSameBytesAsWriteSnapshot(PathsFarSouth(), true);
}

TEST_F(AsyncSnapshotWriterTest, SoftwarePngIsByteIdenticalToWriteSnapshot) {
  options_.use_opengl = false;
  ExpectSameBytesAsWriteSnapshot(PathsBeyondTheRoom());
}

TEST_F(AsyncSnapshotWriterTest, UnwritablePathFailsInFinishNamingIt) {
  AsyncSnapshotWriter writer(m_.get(), options_);
  const std::filesystem::path path = dir_ / "no_such_folder" / "snapshot.png";
  writer.Write(d_.get(), {}, path);
  try {
    writer.Finish();
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

TEST_F(AsyncSnapshotWriterTest, FinishWithoutWriteIsRefusedAndAnUnusedWriterStops) {
  AsyncSnapshotWriter unused(m_.get(), options_);  // its destructor must not wait for a Write
  AsyncSnapshotWriter writer(m_.get(), options_);
  EXPECT_THROW(writer.Finish(), std::logic_error);
}

TEST_F(AsyncSnapshotWriterTest, BadOptionsAreRefusedBeforeAThreadStarts) {
  options_.view.longer_side_px = 3;
  EXPECT_THROW(AsyncSnapshotWriter(m_.get(), options_), std::invalid_argument);
}

}  // namespace
}  // namespace plywood::render
