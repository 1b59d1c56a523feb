#include "sim/world/ground_truth_walls.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "msgs/shortest_number.h"
#include "sim/world/continuing_faces.h"

namespace plywood::sim {
namespace {

struct Pose3 {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
};

Eigen::Matrix3d RotationFromMjQuat(const mjtNum* q) {
  // MuJoCo stores quaternions as (w, x, y, z); normalise in case a user edited model fields.
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
}

// X_WG of a geom from the model alone: body frames composed from the root down. Static bodies
// do not depend on qpos, so this equals what mj_kinematics would put in geom_xpos/xmat.
Pose3 GeomPoseInWorld(const mjModel* m, int geom_id) {
  std::vector<int> chain;
  for (int b = m->geom_bodyid[geom_id]; b != 0; b = m->body_parentid[b]) chain.push_back(b);
  Pose3 X;
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    const int b = *it;
    X.p +=
        X.R * Eigen::Vector3d(m->body_pos[3 * b], m->body_pos[3 * b + 1], m->body_pos[3 * b + 2]);
    X.R = X.R * RotationFromMjQuat(m->body_quat + 4 * b);
  }
  const mjtNum* gp = m->geom_pos + 3 * geom_id;
  X.p += X.R * Eigen::Vector3d(gp[0], gp[1], gp[2]);
  X.R = X.R * RotationFromMjQuat(m->geom_quat + 4 * geom_id);
  return X;
}

}  // namespace

double AxisTiltRad(const Eigen::Matrix3d& R_WG, int axis) {
  return std::atan2(std::hypot(R_WG(0, axis), R_WG(1, axis)), std::abs(R_WG(2, axis)));
}

int BoxAxisNearestVertical(const Eigen::Matrix3d& R_WG) {
  int up = 2;  // z wins a tie, so an upright box keeps its own axes
  for (const int axis : {0, 1}) {
    if (AxisTiltRad(R_WG, axis) < AxisTiltRad(R_WG, up)) up = axis;
  }
  return up;
}

double GeomVerticalHalfExtent(const mjModel* m, int g, const Eigen::Matrix3d& R_WG) {
  const mjtNum* size = m->geom_size + 3 * g;
  // Row 2 of R_WG: how much each of the geom's axes rises per unit along it.
  const double rx = R_WG(2, 0), ry = R_WG(2, 1), rz = R_WG(2, 2);
  switch (m->geom_type[g]) {
    case mjGEOM_BOX:
      return std::abs(rx) * size[0] + std::abs(ry) * size[1] + std::abs(rz) * size[2];
    case mjGEOM_ELLIPSOID:  // the support of the ellipsoid along z
      return std::hypot(rx * size[0], ry * size[1], rz * size[2]);
    case mjGEOM_CYLINDER:  // the axis' rise, and the rim's
      return std::abs(rz) * size[1] + size[0] * std::sqrt(std::max(0.0, 1.0 - rz * rz));
    case mjGEOM_CAPSULE:
      return std::abs(rz) * size[1] + size[0];
    case mjGEOM_SPHERE:
      return size[0];
    default:  // meshes and height fields: their bounding sphere
      return m->geom_rbound[g];
  }
}

namespace {

bool SpansHeight(const GroundTruthOptions& options, double z_min, double z_max) {
  return !options.height_m || (*options.height_m >= z_min && *options.height_m <= z_max);
}

enum class Classification { kSkip, kUpright, kUnrepresented };

// Decides what one geom is for the 2-D description and fills `out` when it is upright.
Classification Classify(const mjModel* m, int g, const GroundTruthOptions& options,
                        UprightGeom* out) {
  const int type = m->geom_type[g];
  if (type == mjGEOM_PLANE || m->geom_group[g] == options.excluded_geom_group ||
      !IsStaticGeom(m, g)) {
    return Classification::kSkip;
  }
  const Pose3 X_WG = GeomPoseInWorld(m, g);
  // The geom's vertical axis: its z, or for a box whichever of its axes stands upright, so a box
  // lying on its side (a wall turned 90 deg about x, a beam written with fromto) is the prism it
  // is.
  const int up = type == mjGEOM_BOX ? BoxAxisNearestVertical(X_WG.R) : 2;
  const double tilt_rad = AxisTiltRad(X_WG.R, up);
  // A sphere is upright in any orientation; a capsule is an upright cylinder with round ends.
  const bool upright = type == mjGEOM_SPHERE || tilt_rad <= options.max_tilt_rad;
  const bool prism_or_round = type == mjGEOM_BOX || type == mjGEOM_CYLINDER ||
                              type == mjGEOM_SPHERE || type == mjGEOM_CAPSULE;
  if (!upright || !prism_or_round) {
    const double half_m = GeomVerticalHalfExtent(m, g, X_WG.R);
    return SpansHeight(options, X_WG.p.z() - half_m, X_WG.p.z() + half_m)
               ? Classification::kUnrepresented
               : Classification::kSkip;
  }
  const mjtNum* size = m->geom_size + 3 * g;
  // The box's horizontal axes, in the order that makes (first, second, up) right-handed.
  const int first = (up + 1) % 3, second = (up + 2) % 3;
  // Half the height of the straight-sided part, and what the round ends add above and below it.
  const bool round_ends = type == mjGEOM_SPHERE || type == mjGEOM_CAPSULE;
  const double half_height =
      type == mjGEOM_BOX ? size[up] : (type == mjGEOM_SPHERE ? 0.0 : size[1]);
  const double end_m = round_ends ? size[0] : 0.0;
  UprightGeom geom;
  geom.shape = type == mjGEOM_BOX ? UprightGeom::Shape::kBox : UprightGeom::Shape::kCylinder;
  geom.geom_id = g;
  geom.centre_W = X_WG.p.head<2>();
  geom.R_WG.col(0) = X_WG.R.block<2, 1>(0, first);
  geom.R_WG.col(1) = X_WG.R.block<2, 1>(0, second);
  geom.z_min_m = X_WG.p.z() - half_height - end_m;
  geom.z_max_m = X_WG.p.z() + half_height + end_m;
  if (!SpansHeight(options, geom.z_min_m, geom.z_max_m)) return Classification::kSkip;
  if (type == mjGEOM_BOX) {
    geom.half_size_xy = Eigen::Vector2d(size[first], size[second]);
  } else if (round_ends && options.height_m) {
    // The disc where the slice cuts a round end: a sphere of radius r cut dz from its centre.
    const double dz = std::max(0.0, std::abs(*options.height_m - X_WG.p.z()) - half_height);
    const double r2 = size[0] * size[0] - dz * dz;
    if (!(r2 > 0.0)) return Classification::kSkip;  // the slice only touches the pole
    geom.radius_m = std::sqrt(r2);
  } else {
    geom.radius_m = size[0];  // a cylinder's disc, or a round shape's outline seen from above
  }
  *out = geom;
  return Classification::kUpright;
}

void AddBoxFaces(const UprightGeom& box, std::vector<WallSegment>* segments) {
  const double hx = box.half_size_xy.x(), hy = box.half_size_xy.y();
  // Counter-clockwise in the box frame; face k runs corner k -> corner k+1.
  const std::array<Eigen::Vector2d, 4> corners_G = {
      Eigen::Vector2d(hx, -hy), Eigen::Vector2d(hx, hy), Eigen::Vector2d(-hx, hy),
      Eigen::Vector2d(-hx, -hy)};
  std::array<Eigen::Vector2d, 4> corners_W;
  for (int k = 0; k < 4; ++k) corners_W[k] = box.centre_W + box.R_WG * corners_G[k];
  // A box flipped upside down projects mirrored: its local counter-clockwise order is clockwise
  // in the world, so swap the ends to keep the outward normal on the right.
  const bool mirrored = box.R_WG.determinant() < 0.0;
  for (int k = 0; k < 4; ++k) {
    WallSegment s;
    s.a = corners_W[k];
    s.b = corners_W[(k + 1) % 4];
    if (mirrored) std::swap(s.a, s.b);
    s.geom_id = box.geom_id;
    s.face_index = k;
    segments->push_back(s);
  }
}

}  // namespace

void GroundTruthOptions::Validate() const {
  if (height_m && !std::isfinite(*height_m)) {
    throw std::invalid_argument("height_m: must be finite, got " + msgs::ShortestNumber(*height_m));
  }
  if (excluded_geom_group < -1 || excluded_geom_group >= mjNGROUP) {
    throw std::invalid_argument("excluded_geom_group: must be -1 (none) or a group in [0, " +
                                std::to_string(mjNGROUP - 1) + "], got " +
                                std::to_string(excluded_geom_group));
  }
  if (!(max_tilt_rad >= 0.0) || !(max_tilt_rad < std::numbers::pi / 2.0)) {
    throw std::invalid_argument("max_tilt_rad: must be in [0, pi/2), got " +
                                msgs::ShortestNumber(max_tilt_rad));
  }
}

bool UprightGeom::ContainsXY(const Eigen::Vector2d& p_W) const {
  const Eigen::Vector2d d = p_W - centre_W;
  if (shape == Shape::kCylinder) return d.squaredNorm() <= radius_m * radius_m;
  // R_WG is orthonormal (rotation or reflection), so its transpose maps world to geom axes.
  const Eigen::Vector2d p_G = R_WG.transpose() * d;
  return std::abs(p_G.x()) <= half_size_xy.x() && std::abs(p_G.y()) <= half_size_xy.y();
}

Eigen::Vector2d WallSegment::OutwardNormal() const {
  const Eigen::Vector2d d = b - a;
  return Eigen::Vector2d(d.y(), -d.x()).normalized();
}

bool IsStaticGeom(const mjModel* model, int geom_id) {
  for (int b = model->geom_bodyid[geom_id]; b != 0; b = model->body_parentid[b]) {
    if (model->body_jntnum[b] > 0 || model->body_mocapid[b] >= 0) return false;
  }
  return true;
}

std::vector<UprightGeom> ExtractUprightGeoms(const mjModel* model,
                                             const GroundTruthOptions& options) {
  options.Validate();
  std::vector<UprightGeom> geoms;
  for (int g = 0; g < model->ngeom; ++g) {
    UprightGeom geom;
    if (Classify(model, g, options, &geom) == Classification::kUpright) geoms.push_back(geom);
  }
  return geoms;
}

GroundTruthWalls ExtractGroundTruthWalls(const mjModel* model, const GroundTruthOptions& options) {
  options.Validate();
  GroundTruthWalls walls;
  for (int g = 0; g < model->ngeom; ++g) {
    UprightGeom geom;
    switch (Classify(model, g, options, &geom)) {
      case Classification::kSkip:
        break;
      case Classification::kUnrepresented:
        walls.unrepresented_geom_ids.push_back(g);
        break;
      case Classification::kUpright:
        if (geom.shape == UprightGeom::Shape::kBox) {
          AddBoxFaces(geom, &walls.segments);
        } else {
          walls.circles.push_back({geom.centre_W, geom.radius_m, g});
        }
        break;
    }
  }
  JoinContinuingFaces(&walls);
  return walls;
}

}  // namespace plywood::sim
