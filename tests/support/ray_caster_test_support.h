#pragma once

// Fixtures shared by the ray casters' tests (MujocoRayCaster, GridRayCaster2D).

#include <Eigen/Core>
#include <string>

#include "sim/world/mujoco_handles.h"

namespace plywood::testing {

// A MuJoCo model compiled from MJCF text, with its data after mj_forward.
struct CompiledWorld {
  sim::MjModelPtr model;
  sim::MjDataPtr data;
  // The id of the geom called `name` (-1 if none).
  int Geom(const char* name) const;
};

// Compiles `mjcf` as if read from <build dir>/<file_name>.
CompiledWorld CompileWorld(const std::string& mjcf, const std::string& file_name);

// A floor, a wall at x = 3, a box yawed by 30 deg, a cylinder, a table top above laser height and
// a "robot" (free body, geom group 3) standing in front of the wall, with `extra_geoms` (MJCF
// lines) added to the worldbody before the robot. Ranges to all of them have closed forms.
std::string ClosedFormWorld(const std::string& extra_geoms = "");

// Expects two unit normals to agree to 1e-12.
void ExpectNormal(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected);

}  // namespace plywood::testing
