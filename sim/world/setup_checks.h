#pragma once

#include <optional>
#include <string>

#include "sim/world/scene.h"

namespace plywood::sim {

// True when the geom hangs under the robot's base body (the robot's own, whatever its group).
bool IsOnTheRobot(const Scene& scene, int geom);

// "geom 'NAME'", or "geom #ID" for an unnamed one: how messages name a geom.
std::string GeomName(const mjModel* m, int geom);

// What makes a compiled scene unfit to simulate, checked after compilation and before the first
// step. Each returns a description of the problem (for a one-line error), or nullopt when fine.

// A geom of the world (not under the robot's base body) in geom group Scene::kRobotGeomGroup:
// the rays, the ground truth, the bumpers and the spawn check take that group for the robot's and
// skip it, while the robot still collides with it, an invisible wall (s44: a seed 001 crate so
// written stopped the robot, encoder ate_rms_m 0.0027 -> 0.755 m, no bump, the truth's area
// without it; MJCF files from elsewhere often put collision geoms in group 3). Checked first: a
// floor in that group is named here, not as a missing floor.
std::optional<std::string> WorldGeomInTheRobotsGroup(const Scene& scene);

// A geom of the world that no geom of the robot can collide with (MuJoCo's contype / conaffinity
// rule, within the robot's height): the robot drives through what its sensors see and the ground
// truth holds, and the spawn check, which reads contacts, never sees it (s44: a floor so written
// let the robot fall, truth distance 0 with the encoders' heading off by 73 deg; the seed 000 rig
// at the origin inside such a crate scored the crate's inside as the room, exit 0).
std::optional<std::string> WorldGeomTheRobotPassesThrough(const Scene& scene);

// A geom of the world, other than a plane, that MuJoCo's rays skip (rgba alpha 0, or its
// material's): no laser, sonar or IR beam sees it, while the robot collides with it and the ground
// truth holds it (s44: a seed 001 crate so written left the sonar map's error at 0.049 where the
// visible crate gives 0.022, exit 0). worlds/README.md asked for an alpha above 0; now checked.
std::optional<std::string> WorldGeomNoSensorSees(const Scene& scene);

// A geom of the world that changes how the robot's own geoms make contact:
// - its contact margin differs from its gap (MuJoCo holds a contact at margin - gap, the larger of
//   the two geoms' each): the robot rides above a floor, or sinks into it, and stops short of a
//   wall or inside it, so its wheels and sensors are not where its file puts them (s44: a hall
//   floor with margin="0.03" took the 40 s square_hall run's encoder ate_rms_m from 0.094 to
//   0.428 m, gap="0.03" to 0.432 m, exit 0);
// - its contact priority is at least the robot's highest (the tires' and casters' 1, which make
//   their own friction, condim and solref decide their contacts "whatever the world's"): the
//   world's then override or mix into them (a floor with priority="2" friction="0.05" gave
//   0.177 m, exit 0).
std::optional<std::string> WorldGeomThatChangesTheRobotsContacts(const Scene& scene);

// The world has no level plane geom at z = 0 for the wheels to stand on (the robot is placed
// there).
std::optional<std::string> MissingFloor(const Scene& scene);

// A static plane geom besides the level floor at z = 0 (a second floor 0.2 m up, a vertical
// plane as a wall): physics and the sensors see an infinite half-space the ground truth (walls,
// rasters) leaves out (a plane at x = 0 threw the robot 1 m in one step, exit 0). Checked after
// MissingFloor.
std::optional<std::string> PlaneThatIsNotTheFloor(const Scene& scene);

// A physics option (<option> or <flag>) other than MuJoCo's default, the timestep aside: the
// world would change the physics every experiment and every other world share (a world with
// gravity="0 0 9.81" ran, the robot afloat, exit 0).
std::optional<std::string> NonDefaultPhysicsOptions(const Scene& scene);

// The first physics option of `option` other than MuJoCo's default, the timestep aside, as "the
// physics option gravity to 0 0 -1 (MuJoCo's default 0 0 -9.81)"; NonDefaultPhysicsOptions' test,
// also applied to the robot's file alone (Scene), whose <option> reached every world it ran in.
std::optional<std::string> PhysicsOptionOffDefault(const mjOption& option);

// A <size> nconmax or njmax below MuJoCo's own (those of a model with nothing in it): MuJoCo
// drops the contacts, or constraint rows, beyond it with only a warning, so the wheels lost the
// floor (a world with <size nconmax="1"/> ran, the encoder ate_rms_m 3.06 m instead of 0.0017,
// exit 0).
std::optional<std::string> ShrunkContactLists(const Scene& scene);

// A geom of the world on a body with a joint or a mocap body: the robot would push it about
// (a free crate in its path ran, exit 0), while walls.csv, the laser's ground truth and the planar
// drive take every world geom as fixed.
std::optional<std::string> MovableWorldGeometry(const Scene& scene);

// The robot, at its spawn pose, overlaps the world's static geometry (a wall, an obstacle) by more
// than a millimetre. Uses MuJoCo's own contacts from the scene's mj_forward: they test the robot's
// real collision geoms (the bumper ring's convex hull, wheels, caster, chassis) with the same
// narrow phase the simulation uses, so "free" means the first step will not push the robot away;
// a 2-D disc test would refuse legitimate spawns near a wall that only the disc touches.
std::optional<std::string> SpawnCollision(const Scene& scene);

// A static geom of the world near `height_m` (within its bounding radius) that the 2-D ground
// truth cannot describe: an ellipsoid, a mesh or a height field, or a box, cylinder or capsule
// tilted from upright (ExtractGroundTruthWalls' unrepresented_geom_ids). The sensors see it while
// walls.csv, the line scores' truth and the occupancy truth leave it out, so a run scored against
// that truth scores it wrong without a word (s43: a seed000 panel leaning 5 deg took
// split_and_merge's precision from 1 to 0.75; a seed 001 obstacle tilted 0.5 deg left the map's
// truth, e 0.0106 -> 0.0259). Checked only for runs that score against the truth at that height.
std::optional<std::string> GeomTheGroundTruthCannotHold(const Scene& scene, double height_m);

// A static geom of the world within the bumper ring's height that the planar drive
// (physics.drive: planar) holds only by the disc of its bounding radius: a box, cylinder or capsule
// tilted from upright, an ellipsoid, a mesh (PlanarObstacles::bounding_disc_geom_ids). The robot
// would stop at that disc, short of what its sensors see and of where the contact drive stops (a
// 2 m panel tilted 3 deg stopped it 1.1 m short), so the run is refused. Also a height field rising
// into the ring's height, which the planar drive passes through. Nullopt in the contact drive.
std::optional<std::string> GeomThePlanarDriveHoldsByItsBound(const Scene& scene);

// The world's static upright geoms span more than an occupancy raster of `resolution_m` cells may
// hold (kMaxOccupancyRasterCells), naming the geom that reaches furthest from the robot: the raster
// a run is scored or drawn with is laid over all of them, so one geom kilometres off (a typo in a
// pos) or kilometres long took every gigabyte the machine had, or ended the run with
// std::bad_alloc after it had run. Checked only for runs that lay such a raster.
std::optional<std::string> WorldTooWideToRasterise(const Scene& scene, double resolution_m);

// The spawn lies outside the horizontal bounding box of the world's static geometry (floor
// excepted): outside every room. A world of nothing but a floor has no outside.
std::optional<std::string> SpawnOutsideWorld(const Scene& scene);

// The same box for any point, "(x, y) is outside every room: ...", or nullopt: a waypoint there is
// never reached (the robot presses into the wall facing it until the run ends).
std::optional<std::string> PointOutsideWorld(const Scene& scene, double x_m, double y_m);

// Why the robot's centre can never be at (x_m, y_m), or nullopt: the point lies inside an upright
// static box or cylinder of the world (a wall, a box, a table leg) that reaches the height of the
// robot's geoms. A waypoint there is never reached: the robot pushes against the geom to the end.
std::optional<std::string> PointInsideWorldGeom(const Scene& scene, double x_m, double y_m);

}  // namespace plywood::sim
