#pragma once

#include <mujoco/mujoco.h>

#include "render/world_to_pixel.h"
#include "viewer/frame_content.h"
#include "viewer/overlay_primitives.h"
#include "viewer/view_controls.h"

namespace plywood::viewer {

// Colours of the overlays (RGBA), shared with the help text and the tests.
namespace overlay_colours {
inline constexpr float kLaserBeam[4] = {1.0f, 0.85f, 0.0f, 1.0f};
inline constexpr float kEcho[4] = {0.1f, 0.8f, 0.2f, 1.0f};
inline constexpr float kSpecularMiss[4] = {1.0f, 0.5f, 0.0f, 1.0f};
inline constexpr float kMultipath[4] = {0.9f, 0.1f, 0.9f, 1.0f};
inline constexpr float kNothing[4] = {0.5f, 0.5f, 0.5f, 0.5f};
inline constexpr float kIr[4] = {0.9f, 0.1f, 0.1f, 1.0f};
inline constexpr float kMatchedLine[4] = {0.0f, 0.9f, 0.0f, 1.0f};
inline constexpr float kUnmatchedLine[4] = {0.95f, 0.0f, 0.0f, 1.0f};
inline constexpr float kFreePartition[4] = {0.0f, 0.75f, 0.85f, 1.0f};
inline constexpr float kObstaclePartition[4] = {0.2f, 0.2f, 0.2f, 1.0f};
inline constexpr float kGraphArc[4] = {0.1f, 0.3f, 0.95f, 1.0f};
inline constexpr float kScaleBar[4] = {0.0f, 0.0f, 0.0f, 1.0f};
inline constexpr float kOccupiedCell[4] = {0.1f, 0.1f, 0.1f, 0.55f};
inline constexpr float kFreeCell[4] = {1.0f, 1.0f, 1.0f, 0.35f};
// Seed 003's map, in geometric_map.png's colours.
inline constexpr float kRealSegment[4] = {0.9f, 0.1f, 0.1f, 1.0f};
inline constexpr float kPseudoSegment[4] = {1.0f, 0.55f, 0.0f, 1.0f};
inline constexpr float kCluster[4] = {0.0f, 0.7f, 0.0f, 1.0f};
}  // namespace overlay_colours

// Adds the overlays `controls` has on: their lines to `lines`, their text labels to `scene` (as
// label geoms, until the scene is full). `world` bounds the floor for the scale bar and axes.
void AddOverlays(mjvScene& scene, OverlayPrimitives& lines, const FrameContent& content,
                 const ViewControls& controls, const render::WorldBounds& world);

}  // namespace plywood::viewer
