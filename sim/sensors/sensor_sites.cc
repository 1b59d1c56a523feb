#include "sim/sensors/sensor_sites.h"

#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "msgs/angle_units.h"
#include "msgs/shortest_number.h"
#include "sim/config/config_error.h"
#include "sim/world/setup_checks.h"

namespace plywood::sim {
namespace {

// Lengths to the millimetre in site errors ("0.34", not "0.33999999999999997").
// The box the robot's geoms fill, in the robot frame: their bounding spheres, placed as the
// robot stands at its spawn; from the floor (z = 0) up to the top of the highest sphere.
struct RobotExtent {
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-std::numeric_limits<double>::infinity(),
                  -std::numeric_limits<double>::infinity()};
  double top_m = 0.0;
  bool empty() const { return !(lo[0] <= hi[0]); }
};

RobotExtent ExtentOfTheRobot(const Scene& scene) {
  const mjModel* m = scene.model();
  const mjData* d = scene.data();
  const int base = scene.base_body_id();
  const Eigen::Vector3d p_WB(d->xpos[3 * base], d->xpos[3 * base + 1], d->xpos[3 * base + 2]);
  const Eigen::Matrix3d R_WB =
      Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(d->xmat + 9 * base);
  RobotExtent extent;
  for (int g = 0; g < m->ngeom; ++g) {
    const double r = m->geom_rbound[g];
    if (!IsOnTheRobot(scene, g) || !(r > 0.0)) continue;  // planes have no bounding sphere
    const Eigen::Vector3d p_B =
        R_WB.transpose() *
        (Eigen::Vector3d(d->geom_xpos[3 * g], d->geom_xpos[3 * g + 1], d->geom_xpos[3 * g + 2]) -
         p_WB);
    for (int axis = 0; axis < 2; ++axis) {
      extent.lo[axis] = std::min(extent.lo[axis], p_B[axis] - r);
      extent.hi[axis] = std::max(extent.hi[axis], p_B[axis] + r);
    }
    extent.top_m = std::max(extent.top_m, p_B.z() + r);
  }
  return extent;
}

// The height in the robot frame of the highest colliding surface of the robot on the vertical
// through the site (over or under it), or nothing when no colliding geom lies there, seen from
// above: a floor-standing wall can then not reach the site without meeting that geom. A vertical
// ray through the site is tested against each colliding geom of the robot alone.
std::optional<double> CollidingSurfaceUnder(const Scene& scene, int site_id, double top_m) {
  const mjModel* m = scene.model();
  const mjData* d = scene.data();
  const int base = scene.base_body_id();
  const Eigen::Vector3d up(d->xmat[9 * base + 2], d->xmat[9 * base + 5], d->xmat[9 * base + 8]);
  const Eigen::Vector3d site(d->site_xpos[3 * site_id], d->site_xpos[3 * site_id + 1],
                             d->site_xpos[3 * site_id + 2]);
  const Eigen::Vector3d base_W(d->xpos[3 * base], d->xpos[3 * base + 1], d->xpos[3 * base + 2]);
  // From above the robot's top, straight down through the site.
  const Eigen::Vector3d start = site + up * (top_m + 1.0 - up.dot(site - base_W));
  const Eigen::Vector3d down = -up;
  std::optional<double> nearest_hit;  // along the ray from `start`
  for (int g = 0; g < m->ngeom; ++g) {
    if (!IsOnTheRobot(scene, g) || (m->geom_contype[g] == 0 && m->geom_conaffinity[g] == 0)) {
      continue;
    }
    double hit = -1.0;
    switch (m->geom_type[g]) {
      case mjGEOM_PLANE:
      case mjGEOM_HFIELD:
        continue;  // not part of a robot's body
      case mjGEOM_MESH:
        hit = mj_rayMesh(m, d, g, start.data(), down.data());
        break;
      default:
        hit = mju_rayGeom(d->geom_xpos + 3 * g, d->geom_xmat + 9 * g, m->geom_size + 3 * g,
                          start.data(), down.data(), m->geom_type[g]);
    }
    if (hit >= 0.0 && (!nearest_hit || hit < *nearest_hit)) nearest_hit = hit;
  }
  if (!nearest_hit) return std::nullopt;
  return up.dot(start + *nearest_hit * down - base_W);
}

// Half the vertical extent of a world geom as placed: exact for boxes, spheres, capsules,
// cylinders and ellipsoids at any angle; the bounding sphere's for meshes and height fields.
double HalfHeight(const mjModel* m, const mjData* d, int g) {
  const mjtNum* r = d->geom_xmat + 9 * g;  // row-major: row 2 is the world's z in the geom's axes
  const mjtNum* size = m->geom_size + 3 * g;
  const double zx = std::abs(r[6]), zy = std::abs(r[7]), zz = std::abs(r[8]);
  switch (m->geom_type[g]) {
    case mjGEOM_BOX:
      return zx * size[0] + zy * size[1] + zz * size[2];
    case mjGEOM_SPHERE:
      return size[0];
    case mjGEOM_CAPSULE:
      return zz * size[1] + size[0];
    case mjGEOM_CYLINDER:
      return zz * size[1] + size[0] * std::sqrt(std::max(0.0, 1.0 - zz * zz));
    case mjGEOM_ELLIPSOID:
      return std::hypot(zx * size[0], zy * size[1], zz * size[2]);
    default:
      return m->geom_rbound[g];
  }
}

// A world geom whose span holds the site's height while its underside clears the robot's colliding
// geoms under the site (a low shelf or table top): the robot's hull passes under it and nothing
// keeps the site out (s54's left item; the hull check above sees floor-standing geoms only).
// Where in the world the robot can reach is not known here, so any such geom is refused.
void RequireNoWorldGeomTheSiteCanEnter(const Scene& scene, int site_id,
                                       const std::string& site_name, double surface_m) {
  const mjModel* m = scene.model();
  const mjData* d = scene.data();
  const int base = scene.base_body_id();
  const double base_z = d->xpos[3 * base + 2];
  const double site_z = d->site_xpos[3 * site_id + 2] - base_z;
  for (int g = 0; g < m->ngeom; ++g) {
    if (IsOnTheRobot(scene, g) || m->body_weldid[m->geom_bodyid[g]] != 0 ||
        m->geom_type[g] == mjGEOM_PLANE) {
      continue;
    }
    const double half = HalfHeight(m, d, g);
    const double bottom = d->geom_xpos[3 * g + 2] - base_z - half;
    const double top = bottom + 2.0 * half;
    if (!(bottom > surface_m && bottom <= site_z && site_z <= top)) continue;
    throw ConfigError(
        scene.world_path().string(), GeomName(m, g),
        "spans z in [" + msgs::MillimetreNumber(bottom) + ", " + msgs::MillimetreNumber(top) +
            "] m, round the site '" + site_name + "' at z " + msgs::MillimetreNumber(site_z) +
            " m, and its underside clears the robot's colliding geoms under that site (their top "
            "at z " +
            msgs::MillimetreNumber(surface_m) +
            " m): the robot can pass under it with the site inside it, every beam starting in it; "
            "raise its underside above the site or model the sensor's mount with a colliding geom "
            "up to the site");
  }
}

// Why a fixed site cannot hold a planar range sensor of `range_max_m`, or nothing.
// `extent`: ExtentOfTheRobot; `surface`: CollidingSurfaceUnder the site.
std::optional<std::string> OffTheRobotOrTilted(const Scene& scene, int site_id, double range_max_m,
                                               const RobotExtent& extent,
                                               std::optional<double> surface) {
  const Eigen::Isometry3d X_BS = scene.SitePoseInBase(site_id);
  const Eigen::Vector3d p = X_BS.translation();
  const std::string at = "the site at (" + msgs::MillimetreNumber(p.x()) + ", " +
                         msgs::MillimetreNumber(p.y()) + ", " + msgs::MillimetreNumber(p.z()) +
                         ") in the robot frame ";
  if (!(p.z() > 0.0)) {
    // The robot frame's origin is on the floor (models/README.md): every beam starts under it.
    return at + "is at or below the floor (z = 0 under the robot)";
  }
  if (!extent.empty() && (p.x() < extent.lo[0] || p.x() > extent.hi[0] || p.y() < extent.lo[1] ||
                          p.y() > extent.hi[1] || p.z() > extent.top_m)) {
    return at + "lies off the robot: its geoms span x in [" + msgs::MillimetreNumber(extent.lo[0]) +
           ", " + msgs::MillimetreNumber(extent.hi[0]) + "], y in [" +
           msgs::MillimetreNumber(extent.lo[1]) + ", " + msgs::MillimetreNumber(extent.hi[1]) +
           "], z in [0, " + msgs::MillimetreNumber(extent.top_m) + "] (their bounding spheres)";
  }
  // A site in a corner of that box, off every colliding geom (s54: the laser at (0.235, 0.3,
  // 0.34) on the P3-DX), is inside a wall whenever the robot stands or passes close to one, and
  // casts every beam from inside it: the hall's east wall read 0.009 to 4.3 m in every beam.
  if (!extent.empty() && !surface) {
    return at +
           "is over no colliding geom of the robot (seen from above): a wall can enclose it "
           "without touching the robot, and its beams would start inside the wall; model its "
           "mount with a colliding geom under it";
  }
  // The beams lie in the site's x-y plane; the steepest of them climbs or drops sin(tilt) per
  // metre, tilt being the angle between the site's z axis and the vertical.
  const Eigen::Vector3d z_B = X_BS.linear().col(2);
  const double sin_tilt = std::hypot(z_B.x(), z_B.y());
  if (range_max_m * sin_tilt > p.z()) {
    const double tilt_deg = std::atan2(sin_tilt, z_B.z()) * kRadToDeg;
    return at + "has its scan plane (its x-y plane) tilted " +
           msgs::ShortestNumber(std::round(tilt_deg * 10.0) / 10.0) + " deg from level: within " +
           "range_max_m " + msgs::ShortestNumber(range_max_m) + " its beams rise or drop " +
           msgs::MillimetreNumber(range_max_m * sin_tilt) + " m, more than its " +
           msgs::MillimetreNumber(p.z()) +
           " m above the floor (scans are logged and used as level)";
  }
  return std::nullopt;
}

}  // namespace

SensorSite RequireSensorSite(const Scene& scene, const std::string& site_name,
                             const std::string& sensor, double range_max_m) {
  const std::optional<int> id = scene.FindSite(site_name);
  if (!id) {
    throw ConfigError(scene.robot_path().string(), site_name,
                      "no such site on the robot; " + sensor + " needs it");
  }
  if (!scene.SiteFixedToBase(*id)) {
    // A joint between the site and the base: its pose in the robot frame changes as it moves,
    // and every scan would be placed with the pose it had when the model was built.
    throw ConfigError(scene.robot_path().string(), site_name,
                      "the site is not fixed to the robot's base body (a joint lies between); " +
                          sensor + " needs a fixed mount");
  }
  // A site off the robot or a steeply tilted one still casts, and the run's figures would be
  // those of a sensor 3 m ahead of the robot, under the floor or looking at it.
  const RobotExtent extent = ExtentOfTheRobot(scene);
  const std::optional<double> surface = CollidingSurfaceUnder(scene, *id, extent.top_m);
  if (const std::optional<std::string> why =
          OffTheRobotOrTilted(scene, *id, range_max_m, extent, surface)) {
    throw ConfigError(scene.robot_path().string(), site_name,
                      *why + "; " + sensor + " needs a " + "level mount on the robot");
  }
  if (surface) RequireNoWorldGeomTheSiteCanEnter(scene, *id, site_name, *surface);
  return {*id, scene.SitePoseInRobot(*id)};
}

std::vector<SensorSite> RequireSensorSites(const Scene& scene,
                                           const std::vector<std::string>& site_names,
                                           const std::string& sensor, double range_max_m) {
  if (site_names.empty()) throw std::invalid_argument("site_names: must not be empty");
  std::vector<SensorSite> sites;
  sites.reserve(site_names.size());
  for (const std::string& name : site_names)
    sites.push_back(RequireSensorSite(scene, name, sensor, range_max_m));
  return sites;
}

std::vector<std::string> NumberedSiteNames(const std::string& prefix, int count) {
  std::vector<std::string> names;
  names.reserve(count);
  for (int i = 0; i < count; ++i) names.push_back(prefix + std::to_string(i));
  return names;
}

}  // namespace plywood::sim
