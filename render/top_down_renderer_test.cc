#include "render/top_down_renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render/geom_footprint.h"
#include "render/image_ops.h"
#include "render/offscreen_context.h"
#include "sim/world/mujoco_handles.h"

namespace plywood::render {
namespace {

// A grey floor, four white walls around a 4 m x 3 m room and a red box off-centre in both axes,
// so a flipped or mirrored picture would move the box's centroid.
constexpr char kRoom[] = R"(
<mujoco>
  <worldbody>
    <geom name="floor" type="plane" size="0 0 1" rgba="0.5 0.5 0.5 1"/>
    <geom type="box" pos="0 1.5 0.25" size="2 0.05 0.25" rgba="0.9 0.9 0.9 1"/>
    <geom type="box" pos="0 -1.5 0.25" size="2 0.05 0.25" rgba="0.9 0.9 0.9 1"/>
    <geom type="box" pos="2 0 0.25" size="0.05 1.5 0.25" rgba="0.9 0.9 0.9 1"/>
    <geom type="box" pos="-2 0 0.25" size="0.05 1.5 0.25" rgba="0.9 0.9 0.9 1"/>
    <geom name="red" type="box" pos="1.1 -0.6 0.15" size="0.2 0.1 0.15" rgba="1 0 0 1"/>
  </worldbody>
</mujoco>)";

const Eigen::Vector2d kRedCentre_W(1.1, -0.6);

struct RedBlob {
  int count = 0;
  Eigen::Vector2d centroid_px = Eigen::Vector2d::Zero();
  Eigen::Vector2d lo_px, hi_px;
};

RedBlob FindRed(const RgbImage& image) {
  RedBlob blob;
  blob.lo_px = Eigen::Vector2d::Constant(1e9);
  blob.hi_px = Eigen::Vector2d::Constant(-1e9);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const Rgb c = PixelAt(image, x, y);
      if (c.r > 120 && c.g < 60 && c.b < 60) {
        const Eigen::Vector2d centre(x + 0.5, y + 0.5);
        ++blob.count;
        blob.centroid_px += centre;
        blob.lo_px = blob.lo_px.cwiseMin(centre);
        blob.hi_px = blob.hi_px.cwiseMax(centre);
      }
    }
  }
  if (blob.count > 0) blob.centroid_px /= blob.count;
  return blob;
}

TEST(TopDownCameraTest, FloorMappingOfTheCameraIsTheFramesMapping) {
  const TopDownFrame frame = FrameBounds({-2.0, 3.0, -1.0, 1.5}, 800);
  const double height_m = TopDownCameraHeightM(800, 0.5);
  const WorldToPixel map =
      FloorMappingOf(MakeTopDownGlCamera(frame, height_m, 0.5), frame.width_px, frame.height_px);
  for (const Eigen::Vector2d& p_W :
       {Eigen::Vector2d(-2.0, 1.5), Eigen::Vector2d(3.0, -1.0), Eigen::Vector2d(0.3, 0.7)}) {
    EXPECT_LT((map.ToPixel(p_W) - frame.world_to_pixel.ToPixel(p_W)).norm(), 0.01)
        << p_W.transpose();
  }
}

TEST(TopDownCameraTest, CameraHeightKeepsParallaxBelowAQuarterPixel) {
  // A point z_top high at the picture's far corner, projected from height D onto the floor.
  for (int px : {256, 1024, 4096}) {
    const double z_top_m = 1.0;
    const double d_m = TopDownCameraHeightM(px, z_top_m);
    const double corner_px = 0.5 * std::sqrt(2.0) * px;  // square picture, worst case
    EXPECT_LT(corner_px * z_top_m / (d_m - z_top_m), 0.25) << px;
  }
}

TEST(TopDownRendererTest, RedBoxLandsWhereWorldToPixelSays) {
  if (!OffscreenRenderingAvailable()) GTEST_SKIP() << "no offscreen OpenGL context here";
  const sim::MjModelPtr m = sim::LoadModelFromString(kRoom, "room.xml");
  const sim::MjDataPtr d(mj_makeData(m.get()));
  mj_forward(m.get(), d.get());
  // 1024 px exceeds the default 640 x 480 offscreen buffer: the renderer must raise it.
  TopDownOptions options;
  options.longer_side_px = 1024;
  TopDownRenderer renderer(m.get(), StaticGeometryExtent(m.get()).bounds, options);
  const TopDownImage out = renderer.Render(d.get());
  ASSERT_EQ(out.image.width, 1024);
  ASSERT_EQ(out.image.height, renderer.frame().height_px);

  const RedBlob blob = FindRed(out.image);
  const double s = out.world_to_pixel.pixels_per_m;
  ASSERT_GT(blob.count, 0);
  const Eigen::Vector2d expected_px = out.world_to_pixel.ToPixel(kRedCentre_W);
  EXPECT_LT((blob.centroid_px - expected_px).norm(), 2.0)
      << "centroid " << blob.centroid_px.transpose() << " expected " << expected_px.transpose();
  // 0.4 m along x (columns) by 0.2 m along y (rows): also checks the picture is not transposed.
  EXPECT_NEAR(blob.hi_px.x() - blob.lo_px.x() + 1.0, 0.4 * s, 3.0);
  EXPECT_NEAR(blob.hi_px.y() - blob.lo_px.y() + 1.0, 0.2 * s, 3.0);
  // Lit from above: the floor is mid-grey, not black.
  const Rgb floor = PixelAt(out.image, static_cast<int>(out.world_to_pixel.ToPixel({-1, 0.5}).x()),
                            static_cast<int>(out.world_to_pixel.ToPixel({-1, 0.5}).y()));
  EXPECT_GT(floor.r, 80);

  // Rendering again after moving nothing gives the same picture (GL state is reused correctly).
  EXPECT_EQ(renderer.Render(d.get()).image.pixels, out.image.pixels);
}

TEST(TopDownRendererTest, SoftwareFallbackUsesTheSameMapping) {
  const sim::MjModelPtr m = sim::LoadModelFromString(kRoom, "room.xml");
  const sim::MjDataPtr d(mj_makeData(m.get()));
  mj_forward(m.get(), d.get());
  const TopDownImage out =
      RenderTopDownSoftware(m.get(), d.get(), StaticGeometryExtent(m.get()).bounds, {});
  const RedBlob blob = FindRed(out.image);
  const double s = out.world_to_pixel.pixels_per_m;
  ASSERT_GT(blob.count, 0);
  EXPECT_LT((blob.centroid_px - out.world_to_pixel.ToPixel(kRedCentre_W)).norm(), 1.0);
  EXPECT_NEAR(blob.count, 0.4 * s * 0.2 * s, 0.6 * s * 0.02 * s);
  // Floor takes the plane's colour.
  EXPECT_EQ(PixelAt(out.image, out.image.width / 2, out.image.height / 4), (Rgb{128, 128, 128}));
}

TEST(TopDownCameraTest, ACutCameraShowsItsBoxOfTheWholePicture) {
  const TopDownFrame frame = FrameBounds({-2.0, 3.0, -1.0, 1.5}, 800);
  const mjvGLCamera whole = MakeTopDownGlCamera(frame, TopDownCameraHeightM(800, 0.5), 0.5);
  const WorldToPixel whole_map = FloorMappingOf(whole, frame.width_px, frame.height_px);
  // The whole box is the whole camera.
  const mjvGLCamera same = CutTopDownGlCamera(whole, frame.width_px, frame.height_px, 0, 0,
                                              frame.width_px, frame.height_px);
  EXPECT_FLOAT_EQ(same.frustum_center, whole.frustum_center);
  EXPECT_FLOAT_EQ(same.frustum_bottom, whole.frustum_bottom);
  EXPECT_FLOAT_EQ(same.frustum_top, whole.frustum_top);
  // A 40 x 30 box whose lower-left pixel is (500, 100), GL rows from the bottom: its picture's
  // pixel (u, v) is the whole picture's (u + 500, v + top row), top row = height - 100 - 30.
  const int x = 500, y_from_bottom = 100, w = 40, h = 30;
  const WorldToPixel cut_map = FloorMappingOf(
      CutTopDownGlCamera(whole, frame.width_px, frame.height_px, x, y_from_bottom, w, h), w, h);
  const Eigen::Vector2d offset(x, frame.height_px - y_from_bottom - h);
  for (const Eigen::Vector2d& p_W :
       {Eigen::Vector2d(0.9, -0.2), Eigen::Vector2d(1.0, -0.1), Eigen::Vector2d(0.95, -0.3)}) {
    EXPECT_LT((cut_map.ToPixel(p_W) + offset - whole_map.ToPixel(p_W)).norm(), 0.01)
        << p_W.transpose();
  }
}

// The room with a free red box and ball (a robot stand-in) and, optionally, a spotlight riding on
// it.
std::string RoomWithAMovingBox(bool light_on_it) {
  std::string xml = kRoom;
  const std::string body =
      std::string(R"(<body name="mover" pos="0 0 0.1"><freejoint/>)") +
      (light_on_it ? R"(<light pos="0 0 1" dir="0 0 -1" diffuse="0.9 0.9 0.9" cutoff="30"/>)"
                   : "") +
      R"(<geom type="box" size="0.15 0.1 0.1" rgba="1 0 0 1"/>)"
      // A sphere's footprint is its bounding circle: nothing but the box's margin covers its rim.
      R"(<geom type="sphere" pos="0.3 0 0" size="0.1" rgba="1 0 0 1"/></body>)";
  // The kRoom's own red box becomes blue, so the red pixels are the moving box's alone.
  const std::string fixed_red = R"(rgba="1 0 0 1"/>
  </worldbody>)";
  xml.replace(xml.find(fixed_red), fixed_red.size(), R"(rgba="0 0 1 1"/>
    )" + body + "\n  </worldbody>");
  return xml;
}

void PlaceMover(const mjModel* m, mjData* d, double x_m, double y_m, double yaw_rad) {
  d->qpos[0] = x_m;
  d->qpos[1] = y_m;
  d->qpos[2] = 0.1;
  d->qpos[3] = std::cos(0.5 * yaw_rad);
  d->qpos[4] = d->qpos[5] = 0.0;
  d->qpos[6] = std::sin(0.5 * yaw_rad);
  mj_forward(m, d);
}

TEST(TopDownRendererTest, OverTheStaticFrameIsRenderBeyondTheMovingBoxAndAlmostWithinIt) {
  if (!OffscreenRenderingAvailable()) GTEST_SKIP() << "no offscreen OpenGL context here";
  const sim::MjModelPtr m = sim::LoadModelFromString(RoomWithAMovingBox(false), "room.xml");
  const sim::MjDataPtr d(mj_makeData(m.get()));
  PlaceMover(m.get(), d.get(), -1.5, 1.2, 0.0);
  TopDownRenderer renderer(m.get(), StaticGeometryExtent(m.get()).bounds);
  renderer.KeepStaticFrame(d.get());
  const double radius_m = 0.4;  // from the body's origin: the sphere's far rim (0.3 + 0.1)
  // Away from where it was when the static frame was drawn, turned, and across a wall's edge.
  for (const Eigen::Vector3d& pose :
       {Eigen::Vector3d(0.3, -0.4, 0.0), Eigen::Vector3d(-0.7, 0.5, 0.6),
        Eigen::Vector3d(1.85, 1.0, 1.2)}) {
    PlaceMover(m.get(), d.get(), pose.x(), pose.y(), pose.z());
    const TopDownImage over = renderer.RenderOverStaticFrame(d.get());
    const TopDownImage whole = renderer.Render(d.get());
    ASSERT_EQ(over.image.width, whole.image.width);
    ASSERT_EQ(over.image.height, whole.image.height);
    const Eigen::Vector2d centre_px = whole.world_to_pixel.ToPixel(pose.head<2>());
    const double reach_px = radius_m * whole.world_to_pixel.pixels_per_m + 3.0;
    int differ = 0, differ_beyond = 0;
    for (int y = 0; y < whole.image.height; ++y) {
      for (int x = 0; x < whole.image.width; ++x) {
        if (PixelAt(over.image, x, y) == PixelAt(whole.image, x, y)) continue;
        ++differ;
        if ((Eigen::Vector2d(x + 0.5, y + 0.5) - centre_px).norm() > reach_px) ++differ_beyond;
      }
    }
    EXPECT_EQ(differ_beyond, 0) << pose.transpose();
    // The box is there (not the static frame's empty floor), up to a few edge pixels.
    const RedBlob over_blob = FindRed(over.image), whole_blob = FindRed(whole.image);
    EXPECT_GT(whole_blob.count, 100) << pose.transpose();
    EXPECT_NEAR(over_blob.count, whole_blob.count, 4) << pose.transpose();
    EXPECT_LE(differ, 8) << pose.transpose();
  }
}

TEST(TopDownRendererTest, OverTheStaticFrameIsRenderWhenThereIsNoStaticFrameOrALightMoves) {
  if (!OffscreenRenderingAvailable()) GTEST_SKIP() << "no offscreen OpenGL context here";
  for (const bool light_on_it : {false, true}) {
    const sim::MjModelPtr m = sim::LoadModelFromString(RoomWithAMovingBox(light_on_it), "room.xml");
    const sim::MjDataPtr d(mj_makeData(m.get()));
    PlaceMover(m.get(), d.get(), -1.5, 1.2, 0.0);
    TopDownRenderer renderer(m.get(), StaticGeometryExtent(m.get()).bounds);
    // With a light riding on the box the static frame lights the floor where the box was.
    if (light_on_it) renderer.KeepStaticFrame(d.get());
    PlaceMover(m.get(), d.get(), 0.8, -0.5, 0.3);
    const TopDownImage over = renderer.RenderOverStaticFrame(d.get());
    EXPECT_EQ(over.image.pixels, renderer.Render(d.get()).image.pixels) << light_on_it;
  }
}

// Pixels where `over` and `whole` differ, and how many of them lie farther than `reach_px` from
// `centre_px`.
struct PixelDiff {
  int differ = 0;
  int beyond = 0;
};

PixelDiff Compare(const RgbImage& over, const RgbImage& whole, const Eigen::Vector2d& centre_px,
                  double reach_px) {
  PixelDiff diff;
  for (int y = 0; y < whole.height; ++y) {
    for (int x = 0; x < whole.width; ++x) {
      if (PixelAt(over, x, y) == PixelAt(whole, x, y)) continue;
      ++diff.differ;
      if ((Eigen::Vector2d(x + 0.5, y + 0.5) - centre_px).norm() > reach_px) ++diff.beyond;
    }
  }
  return diff;
}

// A mocap body (moved through mjData::mocap_pos) is welded to the world as far as body_weldid
// tells, and so is a body on it: the static frame kept them where they were and no box was drawn
// where they went.
TEST(TopDownRendererTest, OverTheStaticFrameMovesAMocapBodyAndWhatHangsOnIt) {
  if (!OffscreenRenderingAvailable()) GTEST_SKIP() << "no offscreen OpenGL context here";
  std::string xml = kRoom;
  const std::string fixed_red = R"(rgba="1 0 0 1"/>
  </worldbody>)";
  xml.replace(xml.find(fixed_red), fixed_red.size(), R"(rgba="0 0 1 1"/>
    <body name="marker" mocap="true" pos="-1.5 1.0 0.1">
      <geom type="box" size="0.15 0.1 0.1" rgba="1 0 0 1"/>
      <body pos="0.3 0 0"><geom type="sphere" size="0.1" rgba="1 0 0 1"/></body>
    </body>
  </worldbody>)");
  const sim::MjModelPtr m = sim::LoadModelFromString(xml, "room.xml");
  const sim::MjDataPtr d(mj_makeData(m.get()));
  mj_forward(m.get(), d.get());
  TopDownRenderer renderer(m.get(), StaticGeometryExtent(m.get()).bounds);
  renderer.KeepStaticFrame(d.get());
  d->mocap_pos[0] = 0.8;
  d->mocap_pos[1] = -0.5;
  mj_forward(m.get(), d.get());
  const TopDownImage over = renderer.RenderOverStaticFrame(d.get());
  const TopDownImage whole = renderer.Render(d.get());
  const RedBlob over_blob = FindRed(over.image), whole_blob = FindRed(whole.image);
  ASSERT_GT(whole_blob.count, 100);
  EXPECT_NEAR(over_blob.count, whole_blob.count, 4);
  EXPECT_LT((over_blob.centroid_px - whole_blob.centroid_px).norm(), 0.5);
  const PixelDiff diff = Compare(over.image, whole.image, whole.world_to_pixel.ToPixel({0.8, -0.5}),
                                 0.4 * whole.world_to_pixel.pixels_per_m + 3.0);
  EXPECT_EQ(diff.beyond, 0);
  EXPECT_LE(diff.differ, 8);
}

// A light of the world whose place or direction follows a moving body (mode trackcom: the world's
// subtree centre of mass is the free body's, the static geoms being massless; mode targetbody:
// it turns to the body) lights the static floor differently wherever the body goes.
TEST(TopDownRendererTest, OverTheStaticFrameIsRenderWhenAStaticLightFollowsAMovingBody) {
  if (!OffscreenRenderingAvailable()) GTEST_SKIP() << "no offscreen OpenGL context here";
  for (const std::string light :
       {R"(<light mode="trackcom" pos="0 0 1.5" dir="0 0 -1" cutoff="25" diffuse="0.9 0.9 0.9"/>)",
        R"(<light mode="targetbody" target="mover" pos="0 0 1.5" dir="0 0 -1" cutoff="25"
                  diffuse="0.9 0.9 0.9"/>)"}) {
    std::string xml = RoomWithAMovingBox(false);
    xml.insert(xml.find("<worldbody>") + std::string("<worldbody>").size(), "\n    " + light);
    const sim::MjModelPtr m = sim::LoadModelFromString(xml, "room.xml");
    const sim::MjDataPtr d(mj_makeData(m.get()));
    PlaceMover(m.get(), d.get(), -1.5, 1.2, 0.0);
    TopDownRenderer renderer(m.get(), StaticGeometryExtent(m.get()).bounds);
    renderer.KeepStaticFrame(d.get());
    PlaceMover(m.get(), d.get(), 0.8, -0.5, 0.3);
    const TopDownImage over = renderer.RenderOverStaticFrame(d.get());
    const TopDownImage whole = renderer.Render(d.get());
    const PixelDiff diff =
        Compare(over.image, whole.image, whole.world_to_pixel.ToPixel({0.8, -0.5}),
                0.4 * whole.world_to_pixel.pixels_per_m + 3.0);
    EXPECT_EQ(diff.beyond, 0) << light;
  }
}

// A skin moves with its bones and no box is made round it: the whole frame is drawn, the very
// bytes of Render. (It comes into the scene as a geom of type mjGEOM_SKIN, object mjOBJ_SKIN:
// MovingBox's check of the objects is what catches it; its nskin check alone does not, a mutation
// found.)
TEST(TopDownRendererTest, OverTheStaticFrameIsRenderWithASkin) {
  if (!OffscreenRenderingAvailable()) GTEST_SKIP() << "no offscreen OpenGL context here";
  std::string xml = RoomWithAMovingBox(false);
  xml.insert(xml.find("<worldbody>"), R"(<asset>
    <skin name="sheet" rgba="1 0 0 1" vertex="-0.2 -0.2 0.3  0.2 -0.2 0.3  0.2 0.2 0.3  -0.2 0.2 0.3"
          face="0 1 2  0 2 3">
      <bone body="mover" bindpos="0 0 0" bindquat="1 0 0 0" vertid="0 1 2 3"
            vertweight="1 1 1 1"/>
    </skin>
  </asset>
  )");
  const sim::MjModelPtr m = sim::LoadModelFromString(xml, "room.xml");
  ASSERT_EQ(m->nskin, 1);
  const sim::MjDataPtr d(mj_makeData(m.get()));
  PlaceMover(m.get(), d.get(), -1.5, 1.2, 0.0);
  TopDownRenderer renderer(m.get(), StaticGeometryExtent(m.get()).bounds);
  renderer.KeepStaticFrame(d.get());
  PlaceMover(m.get(), d.get(), 0.4, -0.3, 0.3);
  const TopDownImage over = renderer.RenderOverStaticFrame(d.get());
  EXPECT_EQ(over.image.pixels, renderer.Render(d.get()).image.pixels);
}

TEST(TopDownOptionsTest, ValidateNamesTheField) {
  TopDownOptions options;
  options.longer_side_px = 0;
  try {
    options.Validate();
    FAIL() << "expected a throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("longer_side_px:", 0), 0u) << e.what();
  }
  options = {};
  options.margin_m = -1.0;
  try {
    options.Validate();
    FAIL() << "expected a throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("margin_m:", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace plywood::render
