#pragma once

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace plywood::sim {

// Which of a compiled model's geoms count as the world's static 2-D geometry.
struct GroundTruthOptions {
  // When set, keep only geoms whose vertical extent [z_min, z_max] contains this height (m), so a
  // laser at 0.34 m does not "see" a table top at 0.72-0.75 m. Unset: every height.
  std::optional<double> height_m;
  // Geoms in this group are the robot's (sim::Scene::kRobotGeomGroup) and never part of the world.
  int excluded_geom_group = 3;
  // A geom is upright when its z axis is within this angle of the world's vertical (either sign).
  double max_tilt_rad = 1e-6;

  // @throws std::invalid_argument naming the field.
  void Validate() const;
};

// A static, upright box or cylinder of the world, seen from above (a box with any of its axes
// upright: its "local x and y" below are then its other two, BoxAxisNearestVertical): the prism
// {p : R_WG^T (p - centre_W) in [-half_size_xy, +half_size_xy]} x [z_min_m, z_max_m] for a box,
// the disc |p - centre_W| <= radius_m for a cylinder. Spheres and upright capsules are kCylinder:
// with GroundTruthOptions::height_m their radius is the disc the slice cuts at that height, else
// their outline seen from above; z_min_m / z_max_m include their round ends.
struct UprightGeom {
  enum class Shape { kBox, kCylinder };
  Shape shape = Shape::kBox;
  int geom_id = -1;
  Eigen::Vector2d centre_W = Eigen::Vector2d::Zero();
  // Columns: the geom's local x and y axes projected on the floor. Orthonormal; a reflection when
  // the geom's upright axis points down.
  Eigen::Matrix2d R_WG = Eigen::Matrix2d::Identity();
  Eigen::Vector2d half_size_xy = Eigen::Vector2d::Zero();  // boxes only
  double radius_m = 0.0;                                   // cylinders only
  double z_min_m = 0.0;
  double z_max_m = 0.0;

  // True when the point lies inside the cross-section or on its boundary.
  bool ContainsXY(const Eigen::Vector2d& p_W) const;
};

// One vertical face of a static upright box, as a 2-D segment in the world frame.
// Orientation: a -> b runs counter-clockwise around the box seen from above (z up), so the
// outward normal is (b - a) turned clockwise by 90 deg: ((b - a).y, -(b - a).x) / |b - a|.
// face_index names the face in the box's own frame: 0 = +x, 1 = +y, 2 = -x, 3 = -y (of its two
// horizontal axes, UprightGeom, for a box lying on its side).
struct WallSegment {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  int geom_id = -1;
  int face_index = 0;

  double LengthM() const { return (b - a).norm(); }
  Eigen::Vector2d OutwardNormal() const;
};

// The cross-section of a static upright cylinder (a round column or a table leg).
struct WallCircle {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius_m = 0.0;
  int geom_id = -1;
};

// One wall surface as every scorer counts it (lines' recall and walls_visible, seed 004's RANSAC
// scores): the faces of one or more boxes that continue one another on one line
// (sim/world/continuing_faces.h), so a wall written as two boxes end to end is one wall. It lies
// on its longest face's line, oriented like it, and a and b are the outermost ends of its faces
// projected onto that line (a surface of one face is that face, bit for bit).
struct WallSurface {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  // Indices into GroundTruthWalls::segments (walls.csv rows), ascending.
  std::vector<int> segments;
  // The row naming the surface in lines.csv: its longest face (the lowest row among faces equal to
  // within the join tolerance), so a reflex corner's long inner face keeps its own row when an
  // 18 mm end face continues it.
  int name = -1;
};

struct GroundTruthWalls {
  std::vector<WallSegment> segments;  // four per box, in geom order then face order
  // The segments joined into surfaces (JoinContinuingFaces): every segment in exactly one, in the
  // order of their first segments; surface_of_segment[k] is segment k's surface.
  std::vector<WallSurface> surfaces;
  std::vector<int> surface_of_segment;
  std::vector<WallCircle> circles;
  // Static geoms that the 2-D description cannot represent (tilted boxes, cylinders and
  // capsules, ellipsoids, meshes, ...), never including planes: callers may warn or fall back to
  // mj_ray for them.
  std::vector<int> unrepresented_geom_ids;
};

// The angle (rad) between a geom's local axis (0, 1, 2: x, y, z; a column of its world rotation
// R_WG) and the world's vertical, either sign.
double AxisTiltRad(const Eigen::Matrix3d& R_WG, int axis);

// The local axis of a box nearest the vertical (z on a tie): a box is an upright prism whichever of
// its axes stands upright, as a wall turned 90 deg about x or a beam written with fromto (its z
// along the beam) does.
int BoxAxisNearestVertical(const Eigen::Matrix3d& R_WG);

// Half the vertical extent of geom g turned by R_WG: exact for boxes, ellipsoids, cylinders,
// capsules and spheres, the bounding radius for meshes and height fields. A capsule lying on the
// floor (fromto at z 0.05, radius 0.05) spans z in [0, 0.1], where its bounding radius (0.35 for a
// 0.6 m capsule) reached the laser's 0.34 m and refused a scored run it could not touch.
double GeomVerticalHalfExtent(const mjModel* model, int geom_id, const Eigen::Matrix3d& R_WG);

// True when the geom's body is welded to the world: no joint anywhere in its chain, not mocap.
bool IsStaticGeom(const mjModel* model, int geom_id);

// The static upright boxes, cylinders, capsules and spheres of `model` (world alone or world +
// robot) that pass `options`, in geom order. Poses come from the model alone (body_pos/quat
// composed down the body tree with geom_pos/quat), so no mjData is needed and qpos does not matter.
// @throws std::invalid_argument if `options` is invalid.
std::vector<UprightGeom> ExtractUprightGeoms(const mjModel* model,
                                             const GroundTruthOptions& options = {});

// The world's wall segments (four vertical faces per upright box), their surfaces and circles
// (upright cylinders and capsules, spheres), skipping planes and the robot's geoms. See UprightGeom
// for what "static" and "upright" mean.
// @throws std::invalid_argument if `options` is invalid.
GroundTruthWalls ExtractGroundTruthWalls(const mjModel* model,
                                         const GroundTruthOptions& options = {});

}  // namespace plywood::sim
