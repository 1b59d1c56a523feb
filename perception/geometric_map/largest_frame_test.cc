#include "perception/geometric_map/largest_frame.h"

#include <gtest/gtest.h>

#include "tests/support/synthetic_scan.h"

namespace plywood::perception {
namespace {

LargestFrame FrameOf(const std::vector<test::Wall>& walls) {
  FusionOptions ir_only;
  ir_only.source = RangeSource::kIrOnly;
  const std::vector<RangePoint> points =
      FuseRanges(test::SyntheticScan(walls, {}, 200, 3.0), nullptr, ir_only);
  const HistogramOptions h;
  return FindLargestFrame(
      MakeDistanceHistograms(points, MakeAngleHistogram(points, h).MainDirectionRad(), h), {});
}

// A dead end open to -x: walls at x = 1.5 and y = 1.0, -0.8 reaching 5 m back, beyond the 3 m
// reach. Three real sides at their distances, the open one pseudo at d_max.
TEST(LargestFrameTest, OpenSideIsPseudoAtDMax) {
  const LargestFrame f =
      FrameOf({{{1.5, -0.8}, {1.5, 1.0}}, {{-5.0, 1.0}, {1.5, 1.0}}, {{-5.0, -0.8}, {1.5, -0.8}}});
  EXPECT_NEAR(f.alpha_rad, 0.0, 1e-9);
  EXPECT_NEAR(f.distance_m[0], 1.5, 1e-9);  // +x
  EXPECT_NEAR(f.distance_m[1], 1.0, 1e-9);  // +y
  EXPECT_DOUBLE_EQ(f.distance_m[2], 3.0);   // -x: d_max
  EXPECT_NEAR(f.distance_m[3], 0.8, 1e-9);  // -y
  EXPECT_FALSE(f.pseudo[0]);
  EXPECT_FALSE(f.pseudo[1]);
  EXPECT_TRUE(f.pseudo[2]);
  EXPECT_FALSE(f.pseudo[3]);
  // The pseudo side's corners, counter-clockwise: (-3, 1) then (-3, -0.8).
  const auto corners = f.SideCorners(2);
  EXPECT_NEAR(corners[0].x(), -3.0, 1e-9);
  EXPECT_NEAR(corners[0].y(), 1.0, 1e-9);
  EXPECT_NEAR(corners[1].x(), -3.0, 1e-9);
  EXPECT_NEAR(corners[1].y(), -0.8, 1e-9);
}

// A closed 3 x 2 m box: every side real; with two boxes' worth of walls on +x (a nearer partial
// wall and the far wall) the frame takes the farthest structure.
TEST(LargestFrameTest, ClosedRoomAllRealFarthestStructureWins) {
  std::vector<test::Wall> walls = test::Rectangle(-1.2, -0.9, 1.8, 1.1);
  const LargestFrame closed = FrameOf(walls);
  EXPECT_NEAR(closed.distance_m[0], 1.8, 1e-9);
  EXPECT_NEAR(closed.distance_m[1], 1.1, 1e-9);
  EXPECT_NEAR(closed.distance_m[2], 1.2, 1e-9);
  EXPECT_NEAR(closed.distance_m[3], 0.9, 1e-9);
  for (bool p : closed.pseudo) EXPECT_FALSE(p);
  // A 0.6 m panel at x = 0.8 hides part of the +x wall; the wall behind still bounds the frame.
  walls.push_back({{0.8, 0.3}, {0.8, 0.9}});
  EXPECT_NEAR(FrameOf(walls).distance_m[0], 1.8, 1e-9);
}

}  // namespace
}  // namespace plywood::perception
