#include "render/top_down_renderer.h"

#include <gtest/gtest.h>

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
