#include "render/world_to_pixel.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace plywood::render {
namespace {

TEST(WorldToPixelTest, MapsKnownPointsAndInverts) {
  // 50 px/m, picture's top-left corner at world (-1, 3).
  const WorldToPixel map{50.0, -1.0, 3.0};
  EXPECT_TRUE(map.ToPixel({-1.0, 3.0}).isApprox(Eigen::Vector2d(0.0, 0.0)));
  EXPECT_TRUE(map.ToPixel({0.0, 0.0}).isApprox(Eigen::Vector2d(50.0, 150.0)));
  // +x goes right, +y goes up (smaller v).
  EXPECT_TRUE(map.ToPixel({1.0, 2.0}).isApprox(Eigen::Vector2d(100.0, 50.0)));
  const Eigen::Vector2d p_W(0.37, -1.21);
  EXPECT_TRUE(map.ToWorld(map.ToPixel(p_W)).isApprox(p_W));
}

TEST(FrameBoundsTest, LongerSideGetsRequestedPixelsAndCornersLandOnEdges) {
  const WorldBounds bounds{-2.0, 2.0, -1.0, 1.0};  // 4 m x 2 m
  const TopDownFrame frame = FrameBounds(bounds, 400);
  EXPECT_EQ(frame.width_px, 400);
  EXPECT_EQ(frame.height_px, 200);
  EXPECT_DOUBLE_EQ(frame.world_to_pixel.pixels_per_m, 100.0);
  EXPECT_TRUE(frame.world_to_pixel.ToPixel({-2.0, 1.0}).isApprox(Eigen::Vector2d(0, 0)));
  EXPECT_TRUE(frame.world_to_pixel.ToPixel({2.0, -1.0}).isApprox(Eigen::Vector2d(400, 200)));
  // The centre of the bounds is the centre of the picture.
  EXPECT_TRUE(frame.world_to_pixel.ToPixel({0.0, 0.0}).isApprox(Eigen::Vector2d(200, 100)));
}

TEST(FrameBoundsTest, TallBoundsRoundShortSideUpAndStayCentred) {
  const WorldBounds bounds{0.0, 1.005, 0.0, 3.0};
  const TopDownFrame frame = FrameBounds(bounds, 300);
  EXPECT_EQ(frame.height_px, 300);
  EXPECT_EQ(frame.width_px, 101);  // 100.5 px rounded up so nothing is cut
  EXPECT_NEAR(frame.shown.width_m(), 1.01, 1e-12);
  const Eigen::Vector2d centre_px = frame.world_to_pixel.ToPixel(bounds.centre());
  EXPECT_NEAR(centre_px.x(), 50.5, 1e-9);
  EXPECT_NEAR(centre_px.y(), 150.0, 1e-9);
}

TEST(FrameBoundsTest, RejectsDegenerateInput) {
  EXPECT_THROW(FrameBounds(WorldBounds::Empty(), 100), std::invalid_argument);
  EXPECT_THROW(FrameBounds({0, 0, 0, 0}, 100), std::invalid_argument);
  EXPECT_THROW(FrameBounds({0, 1, 0, 1}, 1), std::invalid_argument);
}

TEST(WorldBoundsTest, ExtendAndPad) {
  WorldBounds b = WorldBounds::Empty();
  EXPECT_TRUE(b.IsEmpty());
  b.Extend(Eigen::Vector2d(1.0, -2.0));
  b.Extend(Eigen::Vector2d(-1.0, 3.0));
  const WorldBounds padded = b.Padded(0.5);
  EXPECT_DOUBLE_EQ(padded.x_min_m, -1.5);
  EXPECT_DOUBLE_EQ(padded.x_max_m, 1.5);
  EXPECT_DOUBLE_EQ(padded.y_min_m, -2.5);
  EXPECT_DOUBLE_EQ(padded.y_max_m, 3.5);
}

}  // namespace
}  // namespace plywood::render
