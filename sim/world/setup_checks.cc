#include "sim/world/setup_checks.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "msgs/shortest_number.h"
#include "sim/raycast/mujoco_ray_caster.h"
#include "sim/world/ground_truth_walls.h"
#include "sim/world/mujoco_handles.h"
#include "sim/world/occupancy_raster.h"

namespace plywood::sim {

std::string GeomName(const mjModel* m, int geom) {
  const char* name = mj_id2name(m, mjOBJ_GEOM, geom);
  return name ? "geom '" + std::string(name) + "'" : "geom #" + std::to_string(geom);
}

namespace {

// MuJoCo resolves a contact deeper than this by pushing the bodies apart; shallower ones are
// resting contact within its solver's tolerance.
constexpr double kPenetrationToleranceM = 1e-3;

// How far from z = 0, and from level, a floor plane may be: rounding in a world file's numbers,
// far below anything the robot would feel.
constexpr double kFloorToleranceM = 1e-6;
constexpr double kFloorTiltToleranceRad = 1e-6;

// The angle between a plane geom's normal (its local z: column 2 of the row-major geom_xmat) and
// world z.
double PlaneTiltRad(const mjData* d, int geom) {
  const mjtNum* r = d->geom_xmat + 9 * geom;
  return std::atan2(std::hypot(r[2], r[5]), r[8]);
}

bool IsStaticWorldGeom(const Scene& scene, int geom) {
  const mjModel* m = scene.model();
  return !scene.IsRobotGeom(geom) && m->body_weldid[m->geom_bodyid[geom]] == 0;
}

std::string At(const msgs::Pose2D& pose) {
  return "(" + msgs::ShortestNumber(pose.x_m) + ", " + msgs::ShortestNumber(pose.y_m) + ")";
}

// What the robot's geoms collide with, all together (MuJoCo's contype / conaffinity bits), and
// the top of its colliding geoms' bounding spheres.
struct RobotContactMasks {
  int contype = 0, conaffinity = 0;
  double top_m = 0.0;

  explicit RobotContactMasks(const Scene& scene);
  bool CollidesWith(const mjModel* m, int geom) const {
    return (m->geom_contype[geom] & conaffinity) || (contype & m->geom_conaffinity[geom]);
  }
};

RobotContactMasks::RobotContactMasks(const Scene& scene) {
  const mjModel* m = scene.model();
  const mjData* d = scene.data();
  for (int g = 0; g < m->ngeom; ++g) {
    if (!IsOnTheRobot(scene, g)) continue;
    contype |= m->geom_contype[g];
    conaffinity |= m->geom_conaffinity[g];
    if (m->geom_contype[g] || m->geom_conaffinity[g]) {
      top_m = std::max(top_m, d->geom_xpos[3 * g + 2] + m->geom_rbound[g]);
    }
  }
}

// "plane geom 'floor'", "box geom 'crate'": the shape first, for the checks that name planes too.
// A geom's shape in words ("box", "height field"), in mjtGeom order.
std::string Shape(const mjModel* m, int geom) {
  const char* shapes[] = {"plane",     "height field", "sphere", "capsule",
                          "ellipsoid", "cylinder",     "box",    "mesh"};
  const int type = m->geom_type[geom];
  return type >= 0 && type < 8 ? shapes[type] : "shape";
}

std::string ShapeAndName(const mjModel* m, int geom) {
  return Shape(m, geom) + " " + GeomName(m, geom);
}

// "a box tilted 3 deg from upright", "an ellipsoid": the geom's shape with an article, and for a
// box, cylinder or capsule its tilt from upright (a box on whichever axis is nearest vertical).
std::string ShapeAndTilt(const Scene& scene, int geom) {
  const mjModel* m = scene.model();
  const int type = m->geom_type[geom];
  const std::string shape = Shape(m, geom);
  std::string what = (shape.front() == 'e' ? "an " : "a ") + shape;  // "an" for the one vowel
  if (type == mjGEOM_BOX || type == mjGEOM_CYLINDER || type == mjGEOM_CAPSULE) {
    const Eigen::Matrix3d R_WG = Eigen::Map<const Eigen::Matrix<mjtNum, 3, 3, Eigen::RowMajor>>(
        scene.data()->geom_xmat + 9 * geom);
    const int up = type == mjGEOM_BOX ? BoxAxisNearestVertical(R_WG) : 2;
    const double tilt_deg = AxisTiltRad(R_WG, up) * 180.0 / std::numbers::pi;
    what += " tilted " + msgs::ShortestNumber(std::round(tilt_deg * 100.0) / 100.0) +
            " deg from upright";
  }
  return what;
}

}  // namespace

bool IsOnTheRobot(const Scene& scene, int geom) {
  const mjModel* m = scene.model();
  for (int b = m->geom_bodyid[geom]; b != 0; b = m->body_parentid[b]) {
    if (b == scene.base_body_id()) return true;
  }
  return false;
}

std::optional<std::string> GeomTheGroundTruthCannotHold(const Scene& scene, double height_m) {
  const mjModel* m = scene.model();
  GroundTruthOptions options;
  options.height_m = height_m;
  const GroundTruthWalls walls = ExtractGroundTruthWalls(m, options);
  for (const int g : walls.unrepresented_geom_ids) {
    if (!IsStaticWorldGeom(scene, g)) continue;
    const std::string what = ShapeAndTilt(scene, g);
    return "its " + GeomName(m, g) + " is " + what +
           " within reach of z = " + msgs::MillimetreNumber(height_m) +
           " m, where this run is scored: the 2-D ground truth (walls.csv, the line and occupancy "
           "scores) holds only upright boxes, cylinders and capsules, and spheres, so it would "
           "score what the sensors see of it as wrong; make it of those (worlds/README.md)";
  }
  return std::nullopt;
}

std::optional<std::string> GeomThePlanarDriveHoldsByItsBound(const Scene& scene) {
  const mjModel* m = scene.model();
  if (const std::vector<int> fields = scene.PlanarRaisedHeightFields(); !fields.empty()) {
    return "its " + GeomName(m, fields.front()) +
           " is a height field rising into the bumper ring's height: physics.drive: planar takes "
           "height fields for floor and drives through them, where its sensors and the contact "
           "drive meet them; use physics.drive: contact, or make it of upright boxes, cylinders, "
           "capsules and spheres (worlds/README.md)";
  }
  if (const std::vector<int> discs = scene.PlanarBoundingDiscGeoms(); !discs.empty()) {
    const int g = discs.front();
    const std::string what = ShapeAndTilt(scene, g);
    return "its " + GeomName(m, g) + " is " + what +
           " within the bumper ring's height: physics.drive: planar holds only upright boxes (on "
           "any of their axes), cylinders, capsules and spheres, and would stop the robot at this "
           "one's bounding disc (radius " +
           msgs::MillimetreNumber(m->geom_rbound[g]) +
           " m), short of what its sensors see; use physics.drive: contact, or make it of those "
           "(worlds/README.md)";
  }
  return std::nullopt;
}

std::optional<std::string> WorldGeomInTheRobotsGroup(const Scene& scene) {
  const mjModel* m = scene.model();
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_group[g] != Scene::kRobotGeomGroup || IsOnTheRobot(scene, g)) continue;
    return "its " + ShapeAndName(m, g) + " is in geom group " +
           std::to_string(Scene::kRobotGeomGroup) +
           ", the robot's: the sensors' rays, the ground truth, the bumpers and the spawn check "
           "skip that group as the robot's, while the robot still collides with it (an invisible "
           "wall); put it in another group (worlds/README.md)";
  }
  return std::nullopt;
}

std::optional<std::string> WorldGeomTheRobotPassesThrough(const Scene& scene) {
  const mjModel* m = scene.model();
  const mjData* d = scene.data();
  const RobotContactMasks robot(scene);
  for (int g = 0; g < m->ngeom; ++g) {
    if (IsOnTheRobot(scene, g) || m->body_weldid[m->geom_bodyid[g]] != 0 ||
        robot.CollidesWith(m, g)) {
      continue;
    }
    // A plane is infinite; anything else only matters where the robot could meet it, and one no
    // ray sees either is WorldGeomNoSensorSees'.
    const bool plane = m->geom_type[g] == mjGEOM_PLANE;
    const double z_m = d->geom_xpos[3 * g + 2], rbound = m->geom_rbound[g];
    if (!plane && (z_m - rbound > robot.top_m || z_m + rbound < 0.0 || !IsRayVisibleGeom(m, g))) {
      continue;
    }
    return "its " + ShapeAndName(m, g) + " collides with no geom of the robot (contype " +
           std::to_string(m->geom_contype[g]) + ", conaffinity " +
           std::to_string(m->geom_conaffinity[g]) + "; the robot's " +
           std::to_string(robot.contype) + " and " + std::to_string(robot.conaffinity) +
           "): the robot would " +
           (plane ? std::string("fall through it")
                  : std::string("drive through it while its sensors see it and the ground truth "
                                "holds it")) +
           "; leave contype and conaffinity at 1 (worlds/README.md)";
  }
  return std::nullopt;
}

std::optional<std::string> WorldGeomThatChangesTheRobotsContacts(const Scene& scene) {
  const mjModel* m = scene.model();
  int robot_priority = 0;
  for (int g = 0; g < m->ngeom; ++g) {
    if (IsOnTheRobot(scene, g)) robot_priority = std::max(robot_priority, m->geom_priority[g]);
  }
  for (int g = 0; g < m->ngeom; ++g) {
    if (IsOnTheRobot(scene, g)) continue;
    if (m->geom_margin[g] != m->geom_gap[g]) {
      const double held_m = m->geom_margin[g] - m->geom_gap[g];
      return "its " + ShapeAndName(m, g) + " sets margin " +
             msgs::ShortestNumber(m->geom_margin[g]) + " m and gap " +
             msgs::ShortestNumber(m->geom_gap[g]) +
             " m: MuJoCo holds the robot's contacts with it " +
             msgs::ShortestNumber(std::abs(held_m)) + " m " +
             (held_m > 0 ? "apart (the robot rides above a floor so written and stops short of a "
                           "wall)"
                         : "deep (the robot sinks into a floor so written and into a wall)") +
             ", so its wheels and sensors are not where its file puts them; remove margin and gap "
             "(worlds/README.md)";
    }
    if (robot_priority > 0 && m->geom_priority[g] >= robot_priority) {
      return "its " + ShapeAndName(m, g) + " sets contact priority " +
             std::to_string(m->geom_priority[g]) + ", at least the robot's " +
             std::to_string(robot_priority) +
             ": its friction, condim and solref would override or mix into those of the robot's "
             "wheels and casters, which the robot's file sets whatever the world's; remove "
             "priority (worlds/README.md)";
    }
  }
  return std::nullopt;
}

std::optional<std::string> WorldGeomNoSensorSees(const Scene& scene) {
  const mjModel* m = scene.model();
  for (int g = 0; g < m->ngeom; ++g) {
    if (IsOnTheRobot(scene, g) || m->body_weldid[m->geom_bodyid[g]] != 0 ||
        m->geom_type[g] == mjGEOM_PLANE || IsRayVisibleGeom(m, g)) {
      continue;
    }
    const int material = m->geom_matid[g];
    const char* material_name = material >= 0 ? mj_id2name(m, mjOBJ_MATERIAL, material) : nullptr;
    const std::string whose =
        material < 0 ? std::string("its rgba")
                     : "its material " + (material_name ? "'" + std::string(material_name) + "'"
                                                        : "#" + std::to_string(material));
    return "its " + ShapeAndName(m, g) + " is fully transparent (" + whose +
           " has alpha 0): MuJoCo's rays skip it, so no laser, sonar or IR beam sees what the "
           "ground truth" +
           (RobotContactMasks(scene).CollidesWith(m, g)
                ? " and the robot's bumpers and wheels take"
                : " takes (the robot passes through it too)") +
           " for an obstacle; give it an alpha above 0 (worlds/README.md)";
  }
  return std::nullopt;
}

std::optional<std::string> MissingFloor(const Scene& scene) {
  const mjModel* m = scene.model();
  const mjData* d = scene.data();
  int first_plane = -1;
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_type[g] != mjGEOM_PLANE || !IsStaticWorldGeom(scene, g)) continue;
    // The robot is placed with its wheels on z = 0: a floor elsewhere, or tilted, drops it or
    // buries it (a floor 0.3 m up flung the robot round, drift 259 %, exit 0).
    const double z_m = d->geom_xpos[3 * g + 2];
    if (std::abs(z_m) <= kFloorToleranceM &&
        std::abs(PlaneTiltRad(d, g)) <= kFloorTiltToleranceRad) {
      return std::nullopt;
    }
    if (first_plane < 0) first_plane = g;
  }
  if (first_plane < 0)
    return "the world has no floor (a static plane geom the wheels can stand on)";
  const double tilt_deg = PlaneTiltRad(d, first_plane) * 180.0 / std::numbers::pi;
  return "the world has no floor at z = 0: its plane " + GeomName(m, first_plane) +
         " is at z = " + msgs::MillimetreNumber(d->geom_xpos[3 * first_plane + 2]) + " m, tilted " +
         msgs::ShortestNumber(std::round(tilt_deg * 100.0) / 100.0) +
         " deg; the robot stands on z = 0, so put a level floor plane there";
}

std::optional<std::string> PlaneThatIsNotTheFloor(const Scene& scene) {
  const mjModel* m = scene.model();
  const mjData* d = scene.data();
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->geom_type[g] != mjGEOM_PLANE || !IsStaticWorldGeom(scene, g)) continue;
    const double z_m = d->geom_xpos[3 * g + 2];
    const double tilt_rad = PlaneTiltRad(d, g);
    if (std::abs(z_m) <= kFloorToleranceM && std::abs(tilt_rad) <= kFloorTiltToleranceRad) continue;
    const double tilt_deg = tilt_rad * 180.0 / std::numbers::pi;
    return "its plane " + GeomName(m, g) + " is at z = " + msgs::MillimetreNumber(z_m) +
           " m, tilted " + msgs::ShortestNumber(std::round(tilt_deg * 100.0) / 100.0) +
           " deg beside the floor: a plane is an infinite half-space that walls.csv, the laser's "
           "ground truth and the occupancy truth do not hold; make walls of boxes";
  }
  return std::nullopt;
}

std::optional<std::string> NonDefaultPhysicsOptions(const Scene& scene) {
  if (const auto option = PhysicsOptionOffDefault(scene.model()->opt)) {
    return "the world sets " + *option +
           "; every world runs with the same physics (the experiment sets only "
           "physics.timestep_s): remove the world's <option>";
  }
  return std::nullopt;
}

std::optional<std::string> PhysicsOptionOffDefault(const mjOption& o) {
  mjOption defaults;
  mj_defaultOption(&defaults);
  const auto numbers = [](const mjtNum* v, int n) {
    std::string text;
    for (int i = 0; i < n; ++i) text += (i ? " " : "") + msgs::ShortestNumber(v[i]);
    return text;
  };
  const auto refuse = [](const std::string& name, const std::string& value,
                         const std::string& fallback) {
    return "the physics option " + name + " to " + value + " (MuJoCo's default " + fallback + ")";
  };
  // What the world may not change: every option but the timestep (the experiment's
  // physics.timestep_s), the remote API's rate and the magnetic field (no sensor reads it).
  const struct {
    const char* name;
    const mjtNum* value;
    const mjtNum* fallback;
    int n;
  } reals[] = {{"impratio", &o.impratio, &defaults.impratio, 1},
               {"tolerance", &o.tolerance, &defaults.tolerance, 1},
               {"noslip_tolerance", &o.noslip_tolerance, &defaults.noslip_tolerance, 1},
               {"mpr_tolerance", &o.mpr_tolerance, &defaults.mpr_tolerance, 1},
               {"gravity", o.gravity, defaults.gravity, 3},
               {"wind", o.wind, defaults.wind, 3},
               {"density", &o.density, &defaults.density, 1},
               {"viscosity", &o.viscosity, &defaults.viscosity, 1},
               {"o_margin", &o.o_margin, &defaults.o_margin, 1},
               {"o_solref", o.o_solref, defaults.o_solref, mjNREF},
               {"o_solimp", o.o_solimp, defaults.o_solimp, mjNIMP}};
  for (const auto& r : reals) {
    if (std::equal(r.value, r.value + r.n, r.fallback)) continue;
    return refuse(r.name, numbers(r.value, r.n), numbers(r.fallback, r.n));
  }
  const struct {
    const char* name;
    int value;
    int fallback;
  } whole[] = {{"integrator", o.integrator, defaults.integrator},
               {"collision", o.collision, defaults.collision},
               {"cone", o.cone, defaults.cone},
               {"jacobian", o.jacobian, defaults.jacobian},
               {"solver", o.solver, defaults.solver},
               {"iterations", o.iterations, defaults.iterations},
               {"noslip_iterations", o.noslip_iterations, defaults.noslip_iterations},
               {"mpr_iterations", o.mpr_iterations, defaults.mpr_iterations},
               {"disableflags (<flag>)", o.disableflags, defaults.disableflags},
               {"enableflags (<flag>)", o.enableflags, defaults.enableflags}};
  for (const auto& w : whole) {
    if (w.value == w.fallback) continue;
    return refuse(w.name, std::to_string(w.value), std::to_string(w.fallback));
  }
  return std::nullopt;
}

std::optional<std::string> ShrunkContactLists(const Scene& scene) {
  // MuJoCo's own sizes (2.2.2: 100 contacts, 500 constraint rows), from a model with nothing in it.
  static const std::pair<int, int> defaults = [] {
    const MjModelPtr empty = LoadModelFromString("<mujoco/>", "mujoco_defaults.xml");
    return std::pair{empty->nconmax, empty->njmax};
  }();
  const mjModel* m = scene.model();
  const struct {
    const char* name;
    int value;
    int fallback;
    const char* what;
  } sizes[] = {{"nconmax", m->nconmax, defaults.first, "contacts"},
               {"njmax", m->njmax, defaults.second, "constraint rows"}};
  for (const auto& size : sizes) {
    if (size.value >= size.fallback) continue;
    return "the world's <size> sets " + std::string(size.name) + " to " +
           std::to_string(size.value) + ", below MuJoCo's default " +
           std::to_string(size.fallback) + ": MuJoCo drops the " + size.what +
           " beyond it with only a warning (the wheels lose the floor); every world runs with "
           "the same physics: remove the world's <size>";
  }
  return std::nullopt;
}

std::optional<std::string> MovableWorldGeometry(const Scene& scene) {
  const mjModel* m = scene.model();
  for (int g = 0; g < m->ngeom; ++g) {
    int moving = -1;  // the body nearest the world with a joint or mocap, on the geom's way up
    bool robot = scene.IsRobotGeom(g);
    for (int b = m->geom_bodyid[g]; b != 0 && !robot; b = m->body_parentid[b]) {
      robot = b == scene.base_body_id();
      if (m->body_jntnum[b] > 0 || m->body_mocapid[b] >= 0) moving = b;
    }
    if (!robot && moving >= 0) {
      const int b = moving;
      const char* body = mj_id2name(m, mjOBJ_BODY, b);
      return "the world's " + GeomName(m, g) + " can move (its body " +
             (body ? "'" + std::string(body) + "'" : "#" + std::to_string(b)) +
             (m->body_jntnum[b] > 0 ? " has a joint" : " is a mocap body") +
             "); the ground truth takes the world as fixed: a world is static geometry only";
    }
  }
  return std::nullopt;
}

std::optional<std::string> SpawnCollision(const Scene& scene) {
  const mjModel* m = scene.model();
  const mjData* d = scene.data();
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    if (!(c.dist < -kPenetrationToleranceM)) continue;
    const bool robot1 = scene.IsRobotGeom(c.geom1), robot2 = scene.IsRobotGeom(c.geom2);
    if (robot1 == robot2) continue;
    const int world_geom = robot1 ? c.geom2 : c.geom1;
    const int robot_geom = robot1 ? c.geom1 : c.geom2;
    if (m->geom_type[world_geom] == mjGEOM_PLANE) continue;  // the wheels stand on the floor
    return "the robot at " + At(scene.TruePose()) + " overlaps " + GeomName(m, world_geom) +
           " of the world by " + msgs::ShortestNumber(std::round(-c.dist * 1000.0)) + " mm (its " +
           GeomName(m, robot_geom) + ")";
  }
  return std::nullopt;
}

namespace {

// Why (x_m, y_m) lies outside the horizontal bounding box of the world's static geometry (floor
// excepted), or nullopt; "" as `what` names nothing but the point.
std::optional<std::string> OutsideTheWalls(const Scene& scene, double x_m, double y_m,
                                           const std::string& what) {
  const mjModel* m = scene.model();
  const mjData* d = scene.data();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double lo[2] = {kInf, kInf}, hi[2] = {-kInf, -kInf};
  for (int g = 0; g < m->ngeom; ++g) {
    if (!IsStaticWorldGeom(scene, g) || m->geom_type[g] == mjGEOM_PLANE) continue;
    const mjtNum* p = d->geom_xpos + 3 * g;
    const mjtNum* r = d->geom_xmat + 9 * g;  // row-major
    const mjtNum* size = m->geom_size + 3 * g;
    for (int axis = 0; axis < 2; ++axis) {
      // A box's exact extent along the world axis; anything else within its bounding sphere.
      const double half = m->geom_type[g] == mjGEOM_BOX ? std::abs(r[3 * axis]) * size[0] +
                                                              std::abs(r[3 * axis + 1]) * size[1] +
                                                              std::abs(r[3 * axis + 2]) * size[2]
                                                        : m->geom_rbound[g];
      lo[axis] = std::min(lo[axis], p[axis] - half);
      hi[axis] = std::max(hi[axis], p[axis] + half);
    }
  }
  if (!(lo[0] <= hi[0])) return std::nullopt;  // nothing but a floor
  const double xy[2] = {x_m, y_m};
  for (int axis = 0; axis < 2; ++axis) {
    if (!(xy[axis] >= lo[axis] && xy[axis] <= hi[axis])) {
      return what + "(" + msgs::ShortestNumber(x_m) + ", " + msgs::ShortestNumber(y_m) +
             ") is outside every room: the world's walls span x in [" +
             msgs::MillimetreNumber(lo[0]) + ", " + msgs::MillimetreNumber(hi[0]) + "], y in [" +
             msgs::MillimetreNumber(lo[1]) + ", " + msgs::MillimetreNumber(hi[1]) + "]";
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> WorldTooWideToRasterise(const Scene& scene, double resolution_m) {
  OccupancyRasterOptions options;
  options.resolution_m = resolution_m;
  GroundTruthOptions geom_options;
  geom_options.excluded_geom_group = options.excluded_geom_group;
  const std::vector<UprightGeom> geoms = ExtractUprightGeoms(scene.model(), geom_options);
  const Eigen::AlignedBox2d bounds = OccupancyRasterBounds(geoms, options);
  if (bounds.isEmpty()) return std::nullopt;
  const double cells = OccupancyRasterCells(bounds, resolution_m);
  if (cells <= kMaxOccupancyRasterCells) return std::nullopt;
  const msgs::Pose2D spawn = scene.TruePose();
  const Eigen::Vector2d robot(spawn.x_m, spawn.y_m);
  int furthest = -1;
  double furthest_m = -1.0;
  for (const UprightGeom& g : geoms) {
    OccupancyRasterOptions one = options;
    one.bounds_W.reset();
    const Eigen::AlignedBox2d box = OccupancyRasterBounds({g}, one);
    const double reach_m =
        (box.min() - robot).cwiseAbs().cwiseMax((box.max() - robot).cwiseAbs()).norm();
    if (reach_m > furthest_m) {
      furthest_m = reach_m;
      furthest = g.geom_id;
    }
  }
  const double side_m = std::sqrt(kMaxOccupancyRasterCells) * resolution_m;
  return "its static geoms span " + msgs::MillimetreNumber(bounds.sizes().x()) + " x " +
         msgs::MillimetreNumber(bounds.sizes().y()) + " m (" + GeomName(scene.model(), furthest) +
         " reaches " + msgs::MillimetreNumber(furthest_m) +
         " m from the robot): the occupancy raster this run is scored or drawn with, in cells of " +
         msgs::ShortestNumber(resolution_m) + " m, would hold " + msgs::SixDigitNumber(cells) +
         " cells, more than the limit of " + msgs::ShortestNumber(kMaxOccupancyRasterCells) + " (" +
         msgs::ShortestNumber(side_m) + " x " + msgs::ShortestNumber(side_m) +
         " m); keep every geom within that";
}

std::optional<std::string> SpawnOutsideWorld(const Scene& scene) {
  const msgs::Pose2D spawn = scene.TruePose();
  return OutsideTheWalls(scene, spawn.x_m, spawn.y_m, "the robot at ");
}

std::optional<std::string> PointOutsideWorld(const Scene& scene, double x_m, double y_m) {
  return OutsideTheWalls(scene, x_m, y_m, "");
}

std::optional<std::string> PointInsideWorldGeom(const Scene& scene, double x_m, double y_m) {
  const mjModel* m = scene.model();
  const mjData* d = scene.data();
  const double robot_top_m = RobotContactMasks(scene).top_m;
  for (int g = 0; g < m->ngeom; ++g) {
    const int type = m->geom_type[g];
    if (!IsStaticWorldGeom(scene, g) || (type != mjGEOM_BOX && type != mjGEOM_CYLINDER)) continue;
    const mjtNum* p = d->geom_xpos + 3 * g;
    const mjtNum* r = d->geom_xmat + 9 * g;  // row-major; column 2 is the geom's own z
    const mjtNum* size = m->geom_size + 3 * g;
    if (std::abs(r[8]) < 1.0 - 1e-9) continue;  // tilted: its footprint is not its cross-section
    const double half_height = type == mjGEOM_BOX ? size[2] : size[1];
    if (p[2] + half_height < 0.0 || p[2] - half_height > robot_top_m) continue;  // over, under
    const double dx = x_m - p[0], dy = y_m - p[1];
    const double lx = r[0] * dx + r[3] * dy, ly = r[1] * dx + r[4] * dy;  // in the geom's frame
    const bool inside = type == mjGEOM_BOX ? std::abs(lx) < size[0] && std::abs(ly) < size[1]
                                           : std::hypot(lx, ly) < size[0];
    if (inside) {
      return "(" + msgs::ShortestNumber(x_m) + ", " + msgs::ShortestNumber(y_m) + ") lies inside " +
             GeomName(m, g) + " of the world";
    }
  }
  return std::nullopt;
}

}  // namespace plywood::sim
