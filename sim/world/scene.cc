#include "sim/world/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "msgs/shortest_number.h"
#include "perception/logs/regular_file.h"
#include "sim/config/config_error.h"
#include "sim/runner/out_of_memory.h"
#include "sim/world/contact_filter.h"
#include "sim/world/draw_only_geoms.h"
#include "sim/world/finite_geometry.h"
#include "sim/world/planar_drive.h"
#include "sim/world/robot_changed_by_world.h"
#include "sim/world/setup_checks.h"
#include "sim/world/static_geom_step.h"
#include "sim/world/step_skipped_sites.h"
#include "sim/world/upright_pose.h"
#include "sim/world/world_changed_by_robot.h"

namespace plywood::sim {
namespace {

// The file's model compiled alone, or null when it does not compile by itself.
MjModelPtr LoadModelOrNothing(const std::filesystem::path& path) {
  try {
    return LoadModelFromFile(path.string());
  } catch (const OutOfMemory&) {
    throw;  // not the file's fault: said as such
  } catch (const std::exception&) {
    return nullptr;
  }
}

// "'chassis'", or "geom 7" for an unnamed one.
std::string GeomNameOrIndex(const mjModel* m, int geom) {
  const char* name = mj_id2name(m, mjOBJ_GEOM, geom);
  return name != nullptr ? std::string(name) : "geom " + std::to_string(geom);
}

// The world z of a placed geom's lowest point: exact for boxes, spheres, capsules, cylinders,
// ellipsoids and meshes (their vertices); a height field's bounding sphere.
double LowestPointZ(const mjModel* m, const mjData* d, int g) {
  const double* size = m->geom_size + 3 * g;
  const double* R = d->geom_xmat + 9 * g;  // row-major: row 2 holds the local axes' z parts
  const double zx = R[6], zy = R[7], zz = R[8], centre = d->geom_xpos[3 * g + 2];
  switch (m->geom_type[g]) {
    case mjGEOM_SPHERE:
      return centre - size[0];
    case mjGEOM_CAPSULE:
      return centre - size[0] - std::abs(zz) * size[1];
    case mjGEOM_CYLINDER:
      return centre - std::abs(zz) * size[1] - size[0] * std::sqrt(std::max(0.0, 1.0 - zz * zz));
    case mjGEOM_ELLIPSOID:
      return centre - std::sqrt(std::pow(zx * size[0], 2) + std::pow(zy * size[1], 2) +
                                std::pow(zz * size[2], 2));
    case mjGEOM_BOX:
      return centre - std::abs(zx) * size[0] - std::abs(zy) * size[1] - std::abs(zz) * size[2];
    case mjGEOM_MESH: {
      const int mesh = m->geom_dataid[g];
      if (mesh < 0) break;
      double lowest = std::numeric_limits<double>::infinity();
      const float* v = m->mesh_vert + 3 * m->mesh_vertadr[mesh];
      for (int k = 0; k < m->mesh_vertnum[mesh]; ++k, v += 3)
        lowest = std::min(lowest, centre + zx * v[0] + zy * v[1] + zz * v[2]);
      return lowest;
    }
    default:
      break;
  }
  return centre - m->geom_rbound[g];
}

int RequireId(const mjModel* m, mjtObj type, const std::string& name, const std::string& robot) {
  const int id = mj_name2id(m, type, name.c_str());
  if (id < 0) {
    throw ConfigError(robot, name, "the robot model must define this (see models/README.md)");
  }
  return id;
}

// models/README.md's wheel: a hinge about the robot's +y (positive rotation drives forward), free
// to turn for ever, driven by a velocity servo of gear 1 (ctrl is the wheel's rad/s). A robot
// file that breaks one compiled and ran, exit 0, with figures of a robot that barely drove or
// drove another way (s55, default.yaml 10 s, 2.995 m with the shipped file): the right motor on
// the left wheel's joint (a copied line) 0.197 m; a wheel limited to +-30 deg 0.64 m; a wheel
// about z 0.58 m, about -y 0.83 m with encoder drift 104 %; a torque motor 3.47 m, drift 3.3 %;
// gear 2 diverged ("try a smaller physics.timestep_s").
void RequireAWheelTheMotorDrives(const mjModel* m, const mjData* d, int base, int joint, int motor,
                                 const std::string& robot) {
  const std::string joint_name = mj_id2name(m, mjOBJ_JOINT, joint);
  const std::string motor_name = mj_id2name(m, mjOBJ_ACTUATOR, motor);
  if (m->jnt_type[joint] != mjJNT_HINGE) {
    throw ConfigError(robot, joint_name, "the wheel's joint must be a hinge (type=\"hinge\")");
  }
  if (m->jnt_limited[joint]) {
    throw ConfigError(robot, joint_name,
                      "the wheel's hinge is limited (limited=\"true\", range " +
                          msgs::SixDigitNumber(m->jnt_range[2 * joint]) + " to " +
                          msgs::SixDigitNumber(m->jnt_range[2 * joint + 1]) +
                          " rad): a wheel turns for ever; drop the range");
  }
  // The hinge's axis in the world against the base's y axis (xmat is row-major).
  const mjtNum* axis = d->xaxis + 3 * joint;
  const mjtNum* r = d->xmat + 9 * base;
  const double along_y = axis[0] * r[1] + axis[1] * r[4] + axis[2] * r[7];
  if (!(along_y > 1.0 - 1e-6)) {
    throw ConfigError(robot, joint_name,
                      "the wheel's hinge axis must be the robot's +y (axis=\"0 1 0\" in the "
                      "base frame: positive rotation drives forward), but its cosine to +y is " +
                          msgs::SixDigitNumber(along_y));
  }
  if (m->actuator_trntype[motor] != mjTRN_JOINT || m->actuator_trnid[2 * motor] != joint) {
    const int other = m->actuator_trnid[2 * motor];
    const char* acts_on = m->actuator_trntype[motor] == mjTRN_JOINT && other >= 0
                              ? mj_id2name(m, mjOBJ_JOINT, other)
                              : nullptr;
    throw ConfigError(
        robot, motor_name,
        "the motor must drive the joint '" + joint_name + "', but it drives " +
            (acts_on ? "the joint '" + std::string(acts_on) + "'"
                     : std::string("no joint (a tendon, site or body transmission)")) +
            ": the wheel would roll free");
  }
  // <velocity kv="K">: force K * (ctrl - gear * qvel), so the wheel turns at ctrl / gear rad/s.
  const mjtNum* gain = m->actuator_gainprm + mjNGAIN * motor;
  const mjtNum* bias = m->actuator_biasprm + mjNBIAS * motor;
  const bool velocity_servo = m->actuator_dyntype[motor] == mjDYN_NONE &&
                              m->actuator_gaintype[motor] == mjGAIN_FIXED &&
                              m->actuator_biastype[motor] == mjBIAS_AFFINE && gain[0] > 0.0 &&
                              bias[0] == 0.0 && bias[1] == 0.0 && bias[2] == -gain[0];
  if (!velocity_servo || m->actuator_gear[6 * motor] != 1.0) {
    throw ConfigError(
        robot, motor_name,
        "the motor must be a velocity servo of gear 1 (<velocity joint=\"" + joint_name +
            "\" kv=\"...\"/>: the controller's command is the wheel's rad/s), "
            "but it is " +
            (velocity_servo ? "one of gear " + msgs::ShortestNumber(m->actuator_gear[6 * motor])
                            : std::string("another kind (a torque motor, a "
                                          "position servo or a general actuator)")));
  }
}

// models/README.md: the base frame sits under the wheel-axle midpoint, left wheel at +y. Wheels
// swapped side for side drove default.yaml 1.51 m with the encoders' heading 177 deg off, and a
// left axle 0.1 m ahead of the right gave drift 9.5 % (0.29 % as shipped), exit 0 (s55): the
// odometry and the nominal track take the wheels as the README places them.
void RequireTheAxleUnderTheBase(const mjData* d, int base, int left_joint, int right_joint,
                                const std::string& robot) {
  const mjtNum* r = d->xmat + 9 * base;  // row-major: column k is the base's axis k in the world
  const auto in_base = [&](int joint) {
    double p[3];
    for (int k = 0; k < 3; ++k) p[k] = d->xanchor[3 * joint + k] - d->xpos[3 * base + k];
    return std::pair{p[0] * r[0] + p[1] * r[3] + p[2] * r[6],
                     p[0] * r[1] + p[1] * r[4] + p[2] * r[7]};
  };
  const auto [left_x, left_y] = in_base(left_joint);
  const auto [right_x, right_y] = in_base(right_joint);
  const auto at = [&](double x, double y) {
    return "(" + msgs::MillimetreNumber(x) + ", " + msgs::MillimetreNumber(y) + ")";
  };
  if (!(left_y > 0.0 && right_y < 0.0)) {
    throw ConfigError(robot, "left_wheel",
                      "the left wheel's axle is at " + at(left_x, left_y) + " and the right's at " +
                          at(right_x, right_y) +
                          " in the base frame: the left wheel must be on the robot's left (+y), "
                          "the right on its right (models/README.md)");
  }
  for (const auto& [name, x] :
       {std::pair{"left_wheel", left_x}, std::pair{"right_wheel", right_x}}) {
    if (std::abs(x) > Scene::kWheelOnFloorToleranceM) {
      throw ConfigError(robot, name,
                        "the wheel's axle is at x = " + msgs::MillimetreNumber(x) +
                            " m in the base frame; the base frame sits under the wheel-axle "
                            "midpoint (both axles at x = 0 within 1 mm, models/README.md)");
    }
  }
  if (std::abs(left_y + right_y) > Scene::kWheelOnFloorToleranceM) {
    throw ConfigError(robot, "left_wheel",
                      "the axles are at y = " + msgs::MillimetreNumber(left_y) + " and " +
                          msgs::MillimetreNumber(right_y) + " m in the base frame, a midpoint of " +
                          msgs::MillimetreNumber((left_y + right_y) / 2.0) +
                          " m; the base frame sits under the wheel-axle midpoint (y = 0 within "
                          "1 mm, models/README.md)");
  }
}

// Distance from a geom's centre to its farthest point, as the compiler computes it for
// broad-phase culling; must follow any change of a geom's size.
double CylinderBoundingRadius(double radius, double half_length) {
  return std::sqrt(radius * radius + half_length * half_length);
}

// Gives a tire geom the rolling radius `radius`: a cylinder's or sphere's radius, or an ellipsoid's
// two semi-axes in the wheel plane (x and z; y is along the axle), and the matching bounding
// radius.
void SetTireRadius(mjModel* m, int tire, double radius) {
  mjtNum* size = m->geom_size + 3 * tire;
  size[0] = radius;
  if (m->geom_type[tire] == mjGEOM_ELLIPSOID) {
    size[2] = radius;
    m->geom_rbound[tire] = std::max({size[0], size[1], size[2]});
  } else {
    m->geom_rbound[tire] = CylinderBoundingRadius(radius, size[1]);  // a sphere's size[1] is 0
  }
}

// A path as the text of a double-quoted XML attribute: a world named `q"uote.xml` made the
// composed scene malformed XML, refused as "does not compile with robot ...: XML parse error"
// though the world was sound, and one named `x&amp;y.xml` was read as `x&y.xml`, another file,
// which ran under its name (s45).
std::string XmlAttributeText(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

std::string ComposeSceneMjcf(const std::filesystem::path& world, const std::filesystem::path& robot,
                             int placeholder_pairs) {
  // The composed file "lives" in the world's folder so the world's own relative includes, meshes
  // and textures resolve as they would if the user loaded it directly.
  const std::filesystem::path robot_relative =
      std::filesystem::relative(robot, world.parent_path());
  std::string text = "<mujoco model=\"plywood_scene\">\n  <include file=\"" +
                     XmlAttributeText(world.filename().string()) + "\"/>\n  <include file=\"" +
                     XmlAttributeText(robot_relative.string()) + "\"/>\n";
  if (placeholder_pairs > 0) {
    text += "  <contact>\n";
    for (int i = 0; i < placeholder_pairs; ++i) {
      text += "    <pair geom1=\"left_wheel_tire\" geom2=\"right_wheel_tire\"/>\n";
    }
    text += "  </contact>\n";
  }
  return text + "</mujoco>\n";
}

Scene::Scene(const SceneOptions& options) : options_(options) {
  namespace fs = std::filesystem;
  for (const auto& [path, field] :
       {std::pair{options.world_mjcf, "world"}, std::pair{options.robot_mjcf, "robot"}}) {
    if (!perception::IsRegularFile(path)) {
      throw ConfigError(path.string(), "", std::string("no such ") + field + " MJCF file");
    }
  }
  const fs::path world = fs::absolute(options.world_mjcf).lexically_normal();
  const fs::path robot = fs::absolute(options.robot_mjcf).lexically_normal();
  const std::string virtual_path = (world.parent_path() / "__plywood_scene__.xml").string();
  try {
    model_ = LoadModelFromString(ComposeSceneMjcf(world, robot, NearContactPairs::kCapacity),
                                 virtual_path);
  } catch (const OutOfMemory&) {
    // Not the world's fault, as the second compile's line would say.
    throw OutOfMemory("compiling " + world.string() + " with robot " + robot.string());
  } catch (const std::exception&) {
    // Most likely a robot without the tires the placeholder pairs name: compiled without them, the
    // checks below say what is missing.
  }
  if (!model_) {
    try {
      model_ = LoadModelFromString(ComposeSceneMjcf(world, robot), virtual_path);
    } catch (const OutOfMemory&) {
      throw OutOfMemory("compiling " + world.string() + " with robot " + robot.string());
    } catch (const std::exception& e) {
      throw ConfigError(options.world_mjcf.string(), "",
                        std::string("does not compile with robot ") + options.robot_mjcf.string() +
                            ": " + e.what());
    }
  }
  if (const auto problem = NonFiniteGeometry(model_.get())) {
    throw ConfigError(options.world_mjcf.string(), "", *problem);
  }
  // The world's <compiler> and <default> settings reach the robot's file too (angle="radian"
  // turned its sonars and wheels, exit 0): the robot must compile as it does alone.
  // A robot file that does not compile alone is left to the checks below, which name what it lacks.
  if (const MjModelPtr robot_alone = LoadModelOrNothing(robot); robot_alone) {
    if (const auto problem = RobotChangedByWorld(model_.get(), robot_alone.get())) {
      throw ConfigError(options.world_mjcf.string(), "", *problem);
    }
    // A robot file's <option> would change the physics of every world it runs in; named here, as
    // the robot's, before the world's own check would blame the world for it.
    if (const auto option = PhysicsOptionOffDefault(robot_alone->opt)) {
      throw ConfigError(options.robot_mjcf.string(), "",
                        "the robot's file sets " + *option +
                            "; every robot runs with the same physics (the experiment sets only "
                            "physics.timestep_s): remove the robot file's <option>");
    }
  }
  // And the robot's <compiler> and <default> settings reach the world's file: the world must
  // compile as it does alone (a world that does not compile alone is left to the checks below).
  if (const MjModelPtr world_alone = LoadModelOrNothing(world); world_alone) {
    if (const auto problem = WorldChangedByRobot(model_.get(), world_alone.get())) {
      throw ConfigError(options.robot_mjcf.string(), "",
                        "it changes the world " + options.world_mjcf.string() + ": " + *problem);
    }
  }
  if (!(options.timestep_s > 0.0) || !std::isfinite(options.timestep_s)) {
    throw std::invalid_argument("timestep_s: must be a finite number > 0");
  }
  model_->opt.timestep = options.timestep_s;

  const std::string robot_name = options.robot_mjcf.string();
  base_body_ = RequireId(model_.get(), mjOBJ_BODY, "base", robot_name);
  const int free_joint = model_->body_jntadr[base_body_];
  if (free_joint < 0 || model_->jnt_type[free_joint] != mjJNT_FREE) {
    throw ConfigError(robot_name, "base", "the base body must carry a free joint");
  }
  base_qpos_ = model_->jnt_qposadr[free_joint];
  const int left_joint = RequireId(model_.get(), mjOBJ_JOINT, "left_wheel", robot_name);
  const int right_joint = RequireId(model_.get(), mjOBJ_JOINT, "right_wheel", robot_name);
  left_wheel_qpos_ = model_->jnt_qposadr[left_joint];
  right_wheel_qpos_ = model_->jnt_qposadr[right_joint];
  left_wheel_body_ = model_->jnt_bodyid[left_joint];
  right_wheel_body_ = model_->jnt_bodyid[right_joint];
  left_motor_ = RequireId(model_.get(), mjOBJ_ACTUATOR, "left_wheel_motor", robot_name);
  right_motor_ = RequireId(model_.get(), mjOBJ_ACTUATOR, "right_wheel_motor", robot_name);
  left_tire_ = RequireId(model_.get(), mjOBJ_GEOM, "left_wheel_tire", robot_name);
  right_tire_ = RequireId(model_.get(), mjOBJ_GEOM, "right_wheel_tire", robot_name);

  // Spawn: the free joint's reference pose, so mj_resetData returns here.
  mjtNum* qpos0 = model_->qpos0 + base_qpos_;
  // The spawn sets x, y and the heading, not the height the file gives the base: a base at z 0.5
  // dropped the robot at the start, its first scans from 0.84 m, and default.yaml's encoder
  // ate_rms_m read 0.0189 m instead of 0.0054, exit 0 (s55).
  if (std::abs(qpos0[2]) > kWheelOnFloorToleranceM) {
    throw ConfigError(robot_name, "base",
                      "the base body is placed at z = " + msgs::SixDigitNumber(qpos0[2]) +
                          " m; its frame must sit on the floor (z = 0: the spawn sets x, y and the "
                          "heading, not the height; models/README.md)");
  }
  qpos0[0] = options.spawn.x_m;
  qpos0[1] = options.spawn.y_m;
  qpos0[3] = std::cos(options.spawn.theta_rad / 2.0);
  qpos0[4] = 0.0;
  qpos0[5] = 0.0;
  qpos0[6] = std::sin(options.spawn.theta_rad / 2.0);
  InstallTightContactFilter();
  draw_only_geoms_ = DrawOnlyGeoms(model_.get(), kRobotGeomGroup);
  skip_sites_ = StepCanSkipSites(model_.get());
  data_.reset(mj_makeData(model_.get()));
  mj_resetData(model_.get(), data_.get());
  MakeNearContactPairs();
  WithNearPairs([&] { mj_forward(model_.get(), data_.get()); });
  RequireAWheelTheMotorDrives(model_.get(), data_.get(), base_body_, left_joint, left_motor_,
                              robot_name);
  RequireAWheelTheMotorDrives(model_.get(), data_.get(), base_body_, right_joint, right_motor_,
                              robot_name);
  RequireTheAxleUnderTheBase(data_.get(), base_body_, left_joint, right_joint, robot_name);
  RequireRobotOnTheFloor();
  MakePlanarDrive();
}

void Scene::RequireRobotOnTheFloor() const {
  // models/README.md: the base frame sits on the floor, so a tire's lowest point is at its z = 0
  // (SetWheelGeometry keeps it there). A wheel above it spins in the air (the robot rests on its
  // caster and chassis: a 5 s tour drove 2 cm, encoder drift 7332 %); one below it lifts the robot.
  const double base_z = data_->xpos[3 * base_body_ + 2];
  for (const int tire : {left_tire_, right_tire_}) {
    const double lowest_m = data_->geom_xpos[3 * tire + 2] - base_z - model_->geom_size[3 * tire];
    if (std::abs(lowest_m) > kWheelOnFloorToleranceM) {
      throw ConfigError(options_.robot_mjcf.string(), mj_id2name(model_.get(), mjOBJ_GEOM, tire),
                        "the tire's lowest point is " + msgs::MillimetreNumber(std::abs(lowest_m)) +
                            " m " + (lowest_m > 0.0 ? "above" : "below") +
                            " the floor (z = 0 in the robot frame, where the base frame sits: "
                            "models/README.md); put the wheel's axle at the tire's radius, " +
                            msgs::ShortestNumber(model_->geom_size[3 * tire]) + " m, within 1 mm");
    }
  }
  // Nor may another colliding geom reach into the floor: the contact lifts the robot off its
  // wheels (a chassis 5 cm into it: the tour drove 0.2 mm in 5 s, exit 0).
  for (int g = 0; g < model_->ngeom; ++g) {
    if (g == left_tire_ || g == right_tire_ || !IsRobotGeom(g) ||
        model_->geom_type[g] == mjGEOM_PLANE ||
        (model_->geom_contype[g] == 0 && model_->geom_conaffinity[g] == 0)) {
      continue;
    }
    const double lowest_m = LowestPointZ(model_.get(), data_.get(), g) - base_z;
    if (lowest_m < -kWheelOnFloorToleranceM) {
      throw ConfigError(
          options_.robot_mjcf.string(), GeomNameOrIndex(model_.get(), g),
          "the geom collides and reaches " + msgs::MillimetreNumber(-lowest_m) +
              " m below the floor (z = 0 in the robot frame, where the base frame "
              "sits: models/README.md): the floor would lift the robot off its wheels");
    }
  }
}

Scene::~Scene() = default;

void Scene::MakePlanarDrive() {
  if (options_.drive != DriveMode::kPlanar) return;
  PlanarDriveIndices ids;
  ids.base_body = base_body_;
  ids.base_qpos = base_qpos_;
  ids.base_dof = model_->jnt_dofadr[model_->body_jntadr[base_body_]];
  ids.left_joint = model_->body_jntadr[left_wheel_body_];
  ids.right_joint = model_->body_jntadr[right_wheel_body_];
  ids.left_motor = left_motor_;
  ids.right_motor = right_motor_;
  const WheelGeometry g = wheel_geometry();
  ids.left_radius_m = g.left_radius_m;
  ids.right_radius_m = g.right_radius_m;
  ids.track_m = g.track_m;
  planar_ =
      std::make_unique<PlanarDrive>(model_.get(), data_.get(), ids, options_.robot_mjcf.string());
  kinematics_stale_ = false;
}

std::vector<int> Scene::PlanarBoundingDiscGeoms() const {
  if (!planar_) return {};
  return planar_->obstacles().bounding_disc_geom_ids();
}

std::vector<int> Scene::PlanarRaisedHeightFields() const {
  if (!planar_) return {};
  return planar_->obstacles().height_field_geom_ids();
}

std::vector<double> Scene::PlanarContactBearings() const {
  std::vector<double> bearings;
  if (planar_) planar_->ContactBearings(TruePose(), kPlanarContactSkinM, &bearings);
  return bearings;
}

void Scene::MakeNearContactPairs() {
  near_pairs_.reset();
  if (model_->npair != NearContactPairs::kCapacity) return;  // the files bring pairs of their own
  mj_kinematics(model_.get(), data_.get());
  near_pairs_ = std::make_unique<NearContactPairs>(model_.get(), data_.get(), base_body_);
}

msgs::Pose2D Scene::TruePose() const { return UprightPoseFromQpos(data_->qpos + base_qpos_); }

double Scene::TrueYawRateRadS() const {
  // From qvel, not cvel: after mj_step, cvel (like xmat) still describes the state before the
  // integration, one step behind qpos and TruePose(). A free joint's angular velocity is in the
  // body frame; its world z component is the third row of the body's rotation matrix times it.
  const mjtNum* q = data_->qpos + base_qpos_;
  const mjtNum* omega_B = data_->qvel + model_->jnt_dofadr[model_->body_jntadr[base_body_]] + 3;
  const double w = q[3], x = q[4], y = q[5], z = q[6];
  return 2.0 * (x * z - w * y) * omega_B[0] + 2.0 * (y * z + w * x) * omega_B[1] +
         (1.0 - 2.0 * (x * x + y * y)) * omega_B[2];
}

void Scene::PlaceRobot(const msgs::Pose2D& X_WR) {
  WriteUprightPose(X_WR, data_->qpos + base_qpos_);
  WithNearPairs([&] { mj_forward(model_.get(), data_.get()); });
  draw_only_stale_ = false;
  kinematics_stale_ = false;
  bodies_behind_qpos_ = false;
}

void Scene::SetWheelSpeeds(const msgs::WheelSpeedCommand& command) {
  data_->ctrl[left_motor_] = command.left_rad_s;
  data_->ctrl[right_motor_] = command.right_rad_s;
}

double Scene::WheelMotorLimitRadS() const {
  double limit = std::numeric_limits<double>::infinity();
  for (const int motor : {left_motor_, right_motor_}) {
    if (model_->actuator_ctrllimited[motor]) {
      limit = std::min({limit, -model_->actuator_ctrlrange[2 * motor],
                        model_->actuator_ctrlrange[2 * motor + 1]});
    }
  }
  return limit;
}

void Scene::Step() {
  if (planar_) {
    planar_->Step(model_.get(), data_.get());
    kinematics_stale_ = true;
    return;
  }
  // mj_step, bit for bit, without recomputing the static world geoms' poses and without placing
  // the draw-only geoms until something asks for data().
  WithNearPairs([&] {
    if (StepWithStaticWorldGeoms(model_.get(), data_.get(), draw_only_geoms_, skip_sites_)) {
      draw_only_stale_ = true;
    }
  });
  bodies_behind_qpos_ = true;
}

void Scene::PlaceDrawOnlyGeoms() const {
  if (kinematics_stale_) {
    mj_kinematics(model_.get(), data_.get());  // every body, geom and site, draw-only ones too
    // What mj_forward's position stage adds for the renderers: subtree_com (the viewer's follow
    // camera tracks it) and the cameras' and lights' poses.
    mj_comPos(model_.get(), data_.get());
    mj_camlight(model_.get(), data_.get());
    kinematics_stale_ = false;
    draw_only_stale_ = false;
  }
  if (!draw_only_stale_) return;
  PlaceGeoms(model_.get(), data_.get(), draw_only_geoms_);
  if (skip_sites_) PlaceSites(model_.get(), data_.get());
  draw_only_stale_ = false;
}

WheelGeometry Scene::wheel_geometry() const {
  return {model_->geom_size[3 * left_tire_], model_->geom_size[3 * right_tire_],
          model_->body_pos[3 * left_wheel_body_ + 1] - model_->body_pos[3 * right_wheel_body_ + 1]};
}

void Scene::SetWheelGeometry(const WheelGeometry& geometry) {
  if (!(geometry.left_radius_m > 0.0) || !(geometry.right_radius_m > 0.0) ||
      !(geometry.track_m > 0.0)) {
    throw std::invalid_argument("wheel geometry: radii and track must be > 0");
  }
  mjModel* m = model_.get();
  const double centre_y =
      (m->body_pos[3 * left_wheel_body_ + 1] + m->body_pos[3 * right_wheel_body_ + 1]) / 2.0;
  const auto reshape = [&](int body, int tire, double radius, double y) {
    m->body_pos[3 * body + 1] = y;
    m->body_pos[3 * body + 2] = radius;  // axle height: the wheel stands on the floor
    SetTireRadius(m, tire, radius);
    // Visual wheel geoms on the same body follow the tire's radius.
    for (int g = m->body_geomadr[body]; g < m->body_geomadr[body] + m->body_geomnum[body]; ++g) {
      if (g != tire && m->geom_type[g] == mjGEOM_CYLINDER) {
        m->geom_size[3 * g] = radius;
        m->geom_rbound[g] = CylinderBoundingRadius(radius, m->geom_size[3 * g + 1]);
      }
    }
  };
  reshape(left_wheel_body_, left_tire_, geometry.left_radius_m, centre_y + geometry.track_m / 2.0);
  reshape(right_wheel_body_, right_tire_, geometry.right_radius_m,
          centre_y - geometry.track_m / 2.0);
  mj_resetData(m, data_.get());
  MakeNearContactPairs();  // the robot's bounding circle follows its wheels
  WithNearPairs([&] { mj_forward(m, data_.get()); });
  draw_only_stale_ = false;
  MakePlanarDrive();  // the as-built radii and track, and the inertias they give
}

std::optional<int> Scene::FindSite(const std::string& name) const {
  const int id = mj_name2id(model_.get(), mjOBJ_SITE, name.c_str());
  if (id < 0) return std::nullopt;
  return id;
}

bool Scene::SiteFixedToBase(int site_id) const {
  for (int body = model_->site_bodyid[site_id]; body != base_body_;
       body = model_->body_parentid[body]) {
    if (body == 0 || model_->body_jntnum[body] > 0) return false;  // the world, or a joint between
  }
  return true;
}

void Scene::SiteInBaseFrame(int site_id, double pos[3], double quat[4]) const {
  // The site's pose in its body, carried through the bodies welded between it and the base (a
  // user robot's mast).
  mju_copy3(pos, model_->site_pos + 3 * site_id);
  mju_copy4(quat, model_->site_quat + 4 * site_id);
  for (int body = model_->site_bodyid[site_id]; body != base_body_ && body > 0;
       body = model_->body_parentid[body]) {
    mjtNum rotated[3], composed[4];
    mju_rotVecQuat(rotated, pos, model_->body_quat + 4 * body);
    mju_add3(pos, rotated, model_->body_pos + 3 * body);
    mju_mulQuat(composed, model_->body_quat + 4 * body, quat);
    mju_copy4(quat, composed);
  }
}

msgs::Pose2D Scene::SitePoseInRobot(int site_id) const {
  mjtNum pos[3], quat[4];
  SiteInBaseFrame(site_id, pos, quat);
  // Yaw: the site's x axis heading in the horizontal plane.
  const double yaw = std::atan2(2.0 * (quat[0] * quat[3] + quat[1] * quat[2]),
                                1.0 - 2.0 * (quat[2] * quat[2] + quat[3] * quat[3]));
  return {pos[0], pos[1], yaw};
}

double Scene::SiteHeightM(int site_id) const {
  mjtNum pos[3], quat[4];
  SiteInBaseFrame(site_id, pos, quat);
  return pos[2];
}

Eigen::Isometry3d Scene::SitePoseInBase(int site_id) const {
  mjtNum pos[3], quat[4], mat[9];
  SiteInBaseFrame(site_id, pos, quat);
  mju_quat2Mat(mat, quat);
  Eigen::Isometry3d X_BS = Eigen::Isometry3d::Identity();
  X_BS.translation() = Eigen::Vector3d(pos[0], pos[1], pos[2]);
  X_BS.linear() = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(mat);
  return X_BS;
}

Eigen::Isometry3d Scene::SitePoseInWorld(int site_id) const {
  if (model_->site_bodyid[site_id] == base_body_) {
    // The base's sites from qpos as mj_kinematics would place them (a free joint's body frame is
    // its qpos), without placing the rest of the model: the state TruePose() reads. After mj_step
    // site_xpos / site_xmat still describe the state before the integration, one step behind, so
    // every scan was cast 10 ms before its stamp and the true pose logged with it.
    const mjtNum* q = data_->qpos + base_qpos_;
    mjtNum quat[4], site_quat[4], site_mat[9], offset[3];
    mju_copy4(quat, q + 3);
    mju_normalize4(quat);
    mju_mulQuat(site_quat, quat, model_->site_quat + 4 * site_id);
    mju_quat2Mat(site_mat, site_quat);
    mju_rotVecQuat(offset, model_->site_pos + 3 * site_id, quat);
    Eigen::Isometry3d X_WS = Eigen::Isometry3d::Identity();
    X_WS.translation() = Eigen::Vector3d(q[0] + offset[0], q[1] + offset[1], q[2] + offset[2]);
    X_WS.linear() = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(site_mat);
    return X_WS;
  }
  if (bodies_behind_qpos_) {
    // A site on another body (a user robot's pan unit, say) is placed with every body from the
    // current qpos, once a step and only when one is read; physics is unchanged, since mj_step
    // places the bodies afresh from qpos. The shipped robots keep all their sensors on the base.
    kinematics_stale_ = true;
    bodies_behind_qpos_ = false;
  }
  if (kinematics_stale_) PlaceDrawOnlyGeoms();
  // The step left the sites unplaced: this one where mj_step would have put it.
  if (draw_only_stale_ && skip_sites_) PlaceSite(model_.get(), data_.get(), site_id);
  Eigen::Isometry3d X_WS = Eigen::Isometry3d::Identity();
  const mjtNum* p = data_->site_xpos + 3 * site_id;
  const mjtNum* r = data_->site_xmat + 9 * site_id;
  X_WS.translation() = Eigen::Vector3d(p[0], p[1], p[2]);
  X_WS.linear() = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(r);
  return X_WS;
}

}  // namespace plywood::sim
