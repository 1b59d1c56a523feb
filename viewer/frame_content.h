#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "msgs/pose2d.h"
#include "msgs/range_ring.h"

namespace plywood::viewer {

// The latest laser scan, placed in the world.
struct LaserView {
  msgs::Pose2D X_WS;  // sensor pose
  double height_m = 0.0;
  double range_max_m = 0.0;
  std::vector<double> angles_rad;  // in the sensor frame
  std::vector<double> ranges_m;    // >= range_max_m: no return
};

// What one range reading means, from the simulator's view of the same axis.
enum class RingReadingKind {
  kEcho,          // an echo near the true range along the axis
  kSpecularMiss,  // no echo although a wall is within range (the pulse glanced off)
  kMultipath,     // an echo much farther than the nearest surface on the axis
  kNothing,       // no echo and nothing within range
};

// The latest sonar or IR ring, placed in the world.
struct RingView {
  msgs::Pose2D X_WR;  // robot pose when the ring was read
  double height_m = 0.0;
  double half_angle_rad = 0.0;  // cone half-angle (0: a single beam)
  msgs::RangeRing ring;
  std::vector<RingReadingKind> kinds;  // one per reading
};

struct PathView {
  std::string label;
  std::vector<Eigen::Vector2d> points_W;
  float rgba[4] = {0.0f, 0.0f, 0.0f, 1.0f};
};

struct SegmentView {
  Eigen::Vector2d a_W, b_W;
  bool matched = false;  // matched a ground-truth wall
};

// Seed 001's cognitive map as the sonar explorer holds it (its odometry frame, which starts at the
// spawn's world pose, so it overlays the world).
struct MapView {
  struct Box {
    Eigen::Vector2d min_W, max_W;
    bool free = true;
  };
  std::vector<Box> partitions;
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> graph_arcs;  // centre -> door -> centre
};

// Seed 001's occupancy grid: the explorer's cell probabilities (its odometry frame, as MapView).
struct GridView {
  Eigen::Vector2d cell_00_centre_W = Eigen::Vector2d::Zero();
  double cell_m = 0.05;
  int width = 0, height = 0;
  std::vector<float> occupied_p;  // row-major from cell (0, 0), x fastest
};

// Seed 003's geometric map as far as it is built (the map frame: the odometry frame at the first
// scan, which starts at the spawn's world pose).
struct GeometricMapView {
  struct Segment {
    Eigen::Vector2d a_W, b_W;
    bool pseudo = false;  // a side of the largest frame nobody has seen yet
  };
  std::vector<Segment> segments;  // confirmed real and pseudo ones, as geometric_map.png
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> clusters;  // min, max corners
};

// Everything the overlays draw in one frame; the live viewer and the replay both fill it.
struct FrameContent {
  double time_s = 0.0;
  std::optional<LaserView> laser;
  std::optional<RingView> sonar;
  std::optional<RingView> ir;
  std::vector<PathView> paths;  // ground truth first
  std::vector<SegmentView> lines;
  std::optional<MapView> map;
  std::optional<GridView> grid;
  std::optional<GeometricMapView> geometric_map;
};

}  // namespace plywood::viewer
