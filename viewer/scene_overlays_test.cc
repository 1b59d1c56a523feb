// The overlays AddOverlays batches for one frame (no window: the lines are counted, not drawn).

#include "viewer/scene_overlays.h"

#include <gtest/gtest.h>

#include <cstddef>

#include "robot/drive/diff_drive_spec.h"

namespace plywood::viewer {
namespace {

// Line segments in the batch of seed 003's pseudo-segment colour.
std::size_t PseudoSegmentDashes(const GeometricMapView& map) {
  mjvScene scene;
  mjv_defaultScene(&scene);  // no geoms: labels are dropped, lines go to the batch
  OverlayPrimitives lines;
  FrameContent content;
  content.geometric_map = map;
  ViewControls controls(robot::DiffDriveSpec{});
  controls.SetAllOverlays(false);
  controls.set_overlay(Overlay::kMap, true);
  AddOverlays(scene, lines, content, controls, render::WorldBounds{-5.0, 5.0, -5.0, 5.0});
  std::size_t dashes = 0;
  for (const OverlayPrimitives::Batch& batch : lines.batches()) {
    bool pseudo = batch.kind == OverlayPrimitives::Kind::kLines;
    for (int i = 0; i < 4; ++i)
      pseudo = pseudo && batch.rgba[i] == overlay_colours::kPseudoSegment[i];
    if (pseudo) dashes += batch.xyz.size() / 6;
  }
  return dashes;
}

GeometricMapView OnePseudoSegment(double length_m) {
  GeometricMapView map;
  map.segments.push_back({Eigen::Vector2d(0, 0), Eigen::Vector2d(length_m, 0), true});
  return map;
}

// A pseudo segment is dashed 10 cm every 20 cm, as geometric_map.png.
TEST(SceneOverlaysTest, APseudoSegmentIsDashedEveryTwentyCentimetres) {
  EXPECT_EQ(PseudoSegmentDashes(OnePseudoSegment(1.0)), 5u);
  EXPECT_EQ(PseudoSegmentDashes(OnePseudoSegment(1.05)), 6u);
}

// s63: a hand-edited geometric_map.json with a pseudo segment 1e300 m long hung the replay (the
// dash loop's t += 0.2 never reached the length), and one of 1e6 m gave 5 million dashes a frame.
// Beyond 2 km (no room a run maps) the segment is one line.
TEST(SceneOverlaysTest, APseudoSegmentLongerThanAnyRoomIsOneLine) {
  EXPECT_NEAR(static_cast<double>(PseudoSegmentDashes(OnePseudoSegment(500.0))), 2500.0, 1.0);
  EXPECT_EQ(PseudoSegmentDashes(OnePseudoSegment(1e6)), 1u);
}

}  // namespace
}  // namespace plywood::viewer
