#pragma once

// Fixtures shared by the range sensors' tests (laser, sonar, IR ring, IR scanner): an analytic
// ray caster over 2-D wall segments, and MuJoCo worlds whose ranges have closed forms.

#include <Eigen/Geometry>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "msgs/pose2d.h"
#include "sim/raycast/ray_caster.h"
#include "sim/world/scene.h"

namespace plywood::testing {

// A wall as a 2-D segment of unbounded height.
struct Segment {
  Eigen::Vector2d a, b;
  int geom_id;
};

// Exact ranges and normals against segments, for unit tests that need no MuJoCo geometry. Only
// the rays' x-y parts count; the nearest segment wins, the first listed on a tie.
class SegmentCaster : public sim::RayCaster {
 public:
  explicit SegmentCaster(std::vector<Segment> segments) : segments_(std::move(segments)) {}

  bool Cast(const Eigen::Vector3d& origin_W, const Eigen::Vector3d& dir_W, double max_range_m,
            sim::RayHit* hit) const override;

 private:
  std::vector<Segment> segments_;
};

// A point given in a sensor's planar frame, in the world.
Eigen::Vector2d ToWorld(const Eigen::Isometry3d& X_WS, double x, double y);

// An axis-aligned rectangle: a room's interior.
struct Rectangle {
  double x_min, x_max, y_min, y_max;
};

// The rectangle's boundary as segments south, east, north, west with ids first_geom_id.. .
std::vector<Segment> RoomSegments(const Rectangle& interior, int first_geom_id = 1);

// From (px, py) inside `interior`, the distance to its boundary along heading phi_rad and the wall
// it meets ("east" at x_max, "west", "north" at y_max, "south").
std::pair<double, std::string> RoomRange(const Rectangle& interior, double px, double py,
                                         double phi_rad);

// A world of a floor only, written to a fresh temp dir `name`.
std::filesystem::path FloorWorld(const std::string& name);

// A closed room of four 0.1 m thick, 1 m high wall boxes named "east", "west", "north" and
// "south" around `interior` (overlapping at the corners), the whole room rotated by yaw_rad about
// the world origin; written to a fresh temp dir `name`.
std::filesystem::path RoomWorld(const std::string& name, const Rectangle& interior,
                                double yaw_rad = 0.0);

// The shipped robot models/<robot>.xml in `world`, spawned at `spawn`.
sim::SceneOptions RobotIn(const std::string& robot, const std::filesystem::path& world,
                          msgs::Pose2D spawn);

}  // namespace plywood::testing
