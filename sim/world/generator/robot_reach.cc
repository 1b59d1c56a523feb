#include "sim/world/generator/robot_reach.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/world/mujoco_handles.h"

namespace plywood::sim::worldgen {
namespace {

using Eigen::Vector3d;

// Geom `g`'s local point `p` in the world frame.
Vector3d ToWorld(const mjData* d, int g, const Vector3d& p) {
  const mjtNum* x = d->geom_xpos + 3 * g;
  const mjtNum* r = d->geom_xmat + 9 * g;
  return {x[0] + r[0] * p.x() + r[1] * p.y() + r[2] * p.z(),
          x[1] + r[3] * p.x() + r[4] * p.y() + r[5] * p.z(),
          x[2] + r[6] * p.x() + r[7] * p.y() + r[8] * p.z()};
}

double Horizontal(const Vector3d& p) { return std::hypot(p.x(), p.y()); }

double GeomReach(const mjModel* m, const mjData* d, int g) {
  const mjtNum* size = m->geom_size + 3 * g;
  double reach = 0.0;
  switch (m->geom_type[g]) {
    case mjGEOM_BOX:
      for (const double sx : {-1.0, 1.0})
        for (const double sy : {-1.0, 1.0})
          for (const double sz : {-1.0, 1.0})
            reach = std::max(reach,
                             Horizontal(ToWorld(d, g, {sx * size[0], sy * size[1], sz * size[2]})));
      return reach;
    case mjGEOM_SPHERE:
      return Horizontal(ToWorld(d, g, Vector3d::Zero())) + size[0];
    case mjGEOM_CAPSULE:
      for (const double sz : {-1.0, 1.0})
        reach = std::max(reach, Horizontal(ToWorld(d, g, {0, 0, sz * size[1]})) + size[0]);
      return reach;
    case mjGEOM_CYLINDER: {
      // The end circles' rims, finely sampled; the farthest point of a cylinder from a vertical
      // axis lies on one of them. 0.01 % short at most; the spawn margin covers it.
      constexpr int kSamples = 720;
      for (const double sz : {-1.0, 1.0}) {
        for (int k = 0; k < kSamples; ++k) {
          const double a = 2.0 * std::numbers::pi * k / kSamples;
          reach = std::max(
              reach, Horizontal(ToWorld(
                         d, g, {size[0] * std::cos(a), size[0] * std::sin(a), sz * size[1]})));
        }
      }
      return reach;
    }
    case mjGEOM_MESH: {
      const int mesh = m->geom_dataid[g];
      const float* v = m->mesh_vert + 3 * m->mesh_vertadr[mesh];
      for (int k = 0; k < m->mesh_vertnum[mesh]; ++k) {
        reach = std::max(reach, Horizontal(ToWorld(d, g, {v[3 * k], v[3 * k + 1], v[3 * k + 2]})));
      }
      return reach;
    }
    case mjGEOM_PLANE:
      return 0.0;
    default:  // ellipsoids, height fields: their bounding sphere
      return Horizontal(ToWorld(d, g, Vector3d::Zero())) + m->geom_rbound[g];
  }
}

}  // namespace

double RobotReachM(const mjModel* robot) {
  MjDataPtr data(mj_makeData(robot));
  mj_forward(robot, data.get());
  double reach = 0.0;
  for (int g = 0; g < robot->ngeom; ++g) reach = std::max(reach, GeomReach(robot, data.get(), g));
  return reach;
}

namespace {

struct Largest {
  const RobotCatalogEntry* robot = nullptr;
  double reach_m = 0.0;
};

const Largest& FindLargest() {
  static const Largest largest = [] {
    Largest l;
    for (const RobotCatalogEntry& entry : RobotCatalog()) {
      const MjModelPtr model = LoadModelFromFile(entry.mjcf.string());
      const double reach = RobotReachM(model.get());
      if (l.robot == nullptr || reach > l.reach_m) l = {&entry, reach};
    }
    return l;
  }();
  return largest;
}

}  // namespace

const RobotCatalogEntry& LargestRobot() { return *FindLargest().robot; }

double LargestRobotReachM() { return FindLargest().reach_m; }

}  // namespace plywood::sim::worldgen
