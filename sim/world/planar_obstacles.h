#pragma once

#include <mujoco/mujoco.h>

#include <limits>
#include <string>
#include <vector>

#include "msgs/pose2d.h"
#include "sim/world/box_grid_2d.h"

namespace plywood::sim {

// The planar drive's walls (DriveMode::kPlanar): the robot's bumper ring as a 2-D footprint against
// the world's static geoms on the floor plane.
//
// The footprint is the convex hull, on the floor plane, of the vertices of the robot's
// "bumper_ring" mesh geom, in the robot frame, with the ring's height range. The obstacles are the
// static geoms (welded to the world) that could collide with the ring (MuJoCo's contype /
// conaffinity rule) and whose height range meets the ring's: an upright box is its rectangle, an
// upright cylinder, capsule or a sphere its disc (the shapes the ground truth holds, read as
// ExtractUprightGeoms reads them: a box standing on any of its axes is its rectangle), and any
// other shape (tilted boxes, cylinders and capsules, ellipsoids, meshes) the disc of its bounding
// radius, i.e. the robot would stop early beside those: bounding_disc_geom_ids() lists them, and
// a run refuses them (sim::GeomThePlanarDriveHoldsByItsBound).
// Planes and height fields are the floor, never obstacles (height_field_geom_ids() lists those
// rising into the ring's height, which a run refuses). Nothing else of the robot (chassis,
// wheels, laser) is tested: an obstacle above or below the ring's height range is driven under or
// over, as it would be by a robot that touches the world only through its ring.
class PlanarObstacles {
 public:
  // @pre mj_forward (or mj_kinematics) has run on `data`: static geom and robot poses are final.
  // @throws ConfigError naming `robot_file` when the robot has no bumper_ring mesh geom.
  PlanarObstacles(const mjModel* model, const mjData* data, int base_body,
                  const std::string& robot_file);

  // True when the footprint at X_WR overlaps an obstacle with positive depth (touching is not).
  bool Overlaps(const msgs::Pose2D& X_WR);
  // Overlaps(X_WR) for a move from `start`, except that an obstacle the footprint already
  // overlaps at `start` (a spawn within the setup check's tolerance, a PlaceRobot) only counts
  // when the base origin got closer to it: the robot may back out of it, turn or slide along it,
  // but not drive deeper in. Equal to Overlaps(X_WR) when the footprint at `start` is clear.
  bool OverlapsFrom(const msgs::Pose2D& start, const msgs::Pose2D& X_WR);
  // The bearings (robot frame, atan2(y, x) from the base origin) of the footprint's points
  // nearest each obstacle whose gap to the footprint at X_WR is at most skin_m; appended to `out`.
  void ContactBearings(const msgs::Pose2D& X_WR, double skin_m, std::vector<double>* out);
  // Moves X_WR (heading kept) by translations that leave the footprint clear of every obstacle:
  // each round pushes it out of the deepest overlap along that overlap's minimum-translation axis
  // (a rectangle's by separating axes, a disc's along the line from its centre's nearest
  // footprint point), a few rounds for a corner. True and X_WR moved when that takes at most
  // max_push_m in all and ends clear; false and X_WR unchanged otherwise.
  bool PushOut(msgs::Pose2D* X_WR, double max_push_m);

  // The footprint's vertices (robot frame, counter-clockwise) and its distance from the base
  // origin at its farthest vertex.
  const std::vector<double>& footprint_xy() const { return hull_; }
  double reach_m() const { return reach_m_; }
  int obstacle_count() const { return static_cast<int>(obstacles_.size()); }
  // The obstacles held only by the disc of their bounding radius (a tilted box, cylinder or
  // capsule, an ellipsoid, a mesh), which stops the robot short of what its sensors see.
  const std::vector<int>& bounding_disc_geom_ids() const { return bounding_disc_geom_ids_; }
  // The height fields that rise above the ring's lowest point: the drive takes a height field for
  // floor and passes through it, while the sensors and the contact drive meet it.
  const std::vector<int>& height_field_geom_ids() const { return height_field_geom_ids_; }

 private:
  struct Obstacle {
    bool disc = false;
    double cx = 0.0, cy = 0.0;
    double radius_m = 0.0;      // disc
    double ux = 1.0, uy = 0.0;  // rectangle: unit x axis; its y axis is (-uy, ux)
    double half_x = 0.0, half_y = 0.0;
    // Padded distance from the centre to the footprint's farthest point: |dx| or |dy| beyond
    // this plus r puts the footprint farther than r from a point (Near's box test).
    double bound_m = 0.0;
  };
  // Distance from (x, y) to the obstacle's footprint (0 inside).
  static double CentreDistance(const Obstacle& o, double x, double y);
  // The obstacles within kNearPadM of the footprint's circle (radius reach_m) about (x, y),
  // ascending: refreshed when the robot has moved more than half the pad since the last refresh,
  // from the obstacles grid_ lists under a box about (x, y).
  const std::vector<int>& Near(double x, double y);
  // How a disc's centre (robot frame) lies against the footprint: inside it or not, the
  // footprint's boundary point nearest it, and the edge it is least deep behind (the one a disc
  // of radius_m leaves through by the least depth). Gap and Penetration share it.
  struct DiscAgainstFootprint {
    bool centre_inside = true;
    double nearest_m = std::numeric_limits<double>::infinity();
    double nearest_point[2] = {0.0, 0.0};
    double least_depth_m = std::numeric_limits<double>::infinity();
    int least_edge = 0;
  };
  DiscAgainstFootprint AgainstFootprint(const double centre[2], double radius_m) const;
  // Gap (>= 0) between the footprint at X_WR and obstacle `o`; -1 when they overlap. `witness`
  // gets the footprint's point nearest the obstacle (robot frame). With overlap_only, a rectangle
  // found apart returns 0 without its gap or witness.
  double Gap(const Obstacle& o, const msgs::Pose2D& X_WR, double witness[2],
             bool overlap_only) const;

  // The depth (0 when apart or touching) of the footprint at X_WR in obstacle `o`, and the unit
  // direction (world frame) in which moving the robot by that depth separates them.
  double Penetration(const Obstacle& o, const msgs::Pose2D& X_WR, double direction_W[2]) const;

  static constexpr double kNearPadM = 0.5;
  std::vector<int> bounding_disc_geom_ids_;
  std::vector<int> height_field_geom_ids_;
  std::vector<double> hull_;     // x0, y0, x1, y1, ... counter-clockwise
  std::vector<double> normals_;  // outward unit normal of edge i (vertex i to i + 1)
  double reach_m_ = 0.0;
  std::vector<Obstacle> obstacles_;
  // Each obstacle's box of half size bound_m about its centre, in kGridCellM cells.
  static constexpr double kGridCellM = 1.0;
  BoxGrid2D grid_{{}, kGridCellM};
  std::vector<int> grid_hits_;
  std::vector<int> near_;
  double near_x_ = 0.0, near_y_ = 0.0;
  bool near_valid_ = false;
};

}  // namespace plywood::sim
