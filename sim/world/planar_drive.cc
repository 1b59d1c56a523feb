#include "sim/world/planar_drive.h"

#include <algorithm>
#include <cmath>

#include "sim/config/config_error.h"
#include "sim/world/upright_pose.h"

namespace plywood::sim {
namespace {

// Inertia of body b about the world axis `axis` through its centre of mass.
double InertiaAbout(const mjModel* m, const mjData* d, int b, const double axis[3]) {
  const mjtNum* r = d->ximat + 9 * b;  // row-major: column j is principal axis j
  double total = 0.0;
  for (int j = 0; j < 3; ++j) {
    const double along = axis[0] * r[j] + axis[1] * r[3 + j] + axis[2] * r[6 + j];
    total += m->body_inertia[3 * b + j] * along * along;
  }
  return total;
}

// The base's pose after going `fraction` of an arc of length ds and turn dtheta from `start`.
msgs::Pose2D AlongArc(const msgs::Pose2D& start, double ds, double dtheta, double fraction) {
  const double s = fraction * ds, a = fraction * dtheta;
  // Chord of the arc: length s sinc(a / 2), at heading start + a / 2.
  const double half = a / 2.0;
  const double chord = std::abs(half) > 1e-9 ? s * std::sin(half) / half : s;
  const double heading = start.theta_rad + half;
  return {start.x_m + chord * std::cos(heading), start.y_m + chord * std::sin(heading),
          start.theta_rad + a};
}

}  // namespace

PlanarDrive::PlanarDrive(const mjModel* m, const mjData* d, const PlanarDriveIndices& indices,
                         const std::string& robot_file)
    : ids_(indices), obstacles_(m, d, indices.base_body, robot_file) {
  left_qpos_ = m->jnt_qposadr[ids_.left_joint];
  right_qpos_ = m->jnt_qposadr[ids_.right_joint];
  left_dof_ = m->jnt_dofadr[ids_.left_joint];
  right_dof_ = m->jnt_dofadr[ids_.right_joint];

  // The servos: velocity actuators (gain kv, bias -kv x velocity) with equal gear and gain.
  double k[2], gain[2];
  const int motors[2] = {ids_.left_motor, ids_.right_motor};
  const int dofs[2] = {left_dof_, right_dof_};
  for (int i = 0; i < 2; ++i) {
    const int a = motors[i];
    const double kv = m->actuator_gainprm[mjNGAIN * a];
    const double gear = m->actuator_gear[6 * a];
    if (m->actuator_gaintype[a] != mjGAIN_FIXED || m->actuator_biastype[a] != mjBIAS_AFFINE ||
        !(kv > 0.0) || m->actuator_biasprm[mjNBIAS * a + 1] != 0.0 ||
        m->actuator_biasprm[mjNBIAS * a + 2] != -kv || m->actuator_trntype[a] != mjTRN_JOINT) {
      throw ConfigError(robot_file, i == 0 ? "left_wheel_motor" : "right_wheel_motor",
                        "physics.drive: planar needs <velocity> actuators on the wheel joints");
    }
    k[i] = gear * gear * kv + m->dof_damping[dofs[i]];
    gain[i] = gear * kv / k[i];
    if (m->actuator_ctrllimited[a]) {
      ctrl_lo_ = std::max(ctrl_lo_, m->actuator_ctrlrange[2 * a]);
      ctrl_hi_ = std::min(ctrl_hi_, m->actuator_ctrlrange[2 * a + 1]);
    }
  }
  stiffness_ = (k[0] + k[1]) / 2.0;
  command_gain_ = (gain[0] + gain[1]) / 2.0;

  // Mass, yaw inertia about the base origin's vertical, and the wheels' axle inertia.
  const int root = m->body_rootid[ids_.base_body];
  const mjtNum* origin = d->xpos + 3 * ids_.base_body;
  const double up[3] = {0.0, 0.0, 1.0};
  double mass = 0.0, yaw_inertia = 0.0;
  for (int b = 1; b < m->nbody; ++b) {
    if (m->body_rootid[b] != root) continue;
    const double dx = d->xipos[3 * b] - origin[0], dy = d->xipos[3 * b + 1] - origin[1];
    mass += m->body_mass[b];
    yaw_inertia += InertiaAbout(m, d, b, up) + m->body_mass[b] * (dx * dx + dy * dy);
  }
  double wheel_inertia = 0.0;
  for (const int joint : {ids_.left_joint, ids_.right_joint}) {
    wheel_inertia += (InertiaAbout(m, d, m->jnt_bodyid[joint], d->xaxis + 3 * joint) +
                      m->dof_armature[m->jnt_dofadr[joint]]) /
                     2.0;
  }
  const double r = (ids_.left_radius_m + ids_.right_radius_m) / 2.0;
  const double b = ids_.track_m;
  straight_inertia_ = wheel_inertia + mass * r * r / 2.0;
  turn_inertia_ = wheel_inertia + 2.0 * yaw_inertia * r * r / (b * b);
}

void PlanarDrive::Step(const mjModel* m, mjData* d) {
  const double dt = m->opt.timestep;
  double u_left = std::clamp(d->ctrl[ids_.left_motor], ctrl_lo_, ctrl_hi_);
  double u_right = std::clamp(d->ctrl[ids_.right_motor], ctrl_lo_, ctrl_hi_);
  // As mj_fwdActuation: a NaN or huge control (after the clamp) zeroes every control for the step
  // and raises mjWARN_BADCTRL; d->ctrl itself is kept.
  if (mju_isBad(u_left) || mju_isBad(u_right)) {
    mj_warning(d, mjWARN_BADCTRL, mju_isBad(u_left) ? ids_.left_motor : ids_.right_motor);
    u_left = 0.0;
    u_right = 0.0;
  }
  const double target_s = command_gain_ * (u_left + u_right) / 2.0;
  const double target_d = command_gain_ * (u_right - u_left) / 2.0;
  double s = (d->qvel[left_dof_] + d->qvel[right_dof_]) / 2.0;
  double half_diff = (d->qvel[right_dof_] - d->qvel[left_dof_]) / 2.0;
  s += std::min(1.0, dt * stiffness_ / straight_inertia_) * (target_s - s);
  half_diff += std::min(1.0, dt * stiffness_ / turn_inertia_) * (target_d - half_diff);
  const double w_left = s - half_diff, w_right = s + half_diff;

  const double v = (ids_.right_radius_m * w_right + ids_.left_radius_m * w_left) / 2.0;
  const double yaw_rate =
      (ids_.right_radius_m * w_right - ids_.left_radius_m * w_left) / ids_.track_m;
  mjtNum* q = d->qpos + ids_.base_qpos;
  const msgs::Pose2D start = UprightPoseFromQpos(q);
  const double ds = v * dt, dtheta = yaw_rate * dt;
  const msgs::Pose2D whole = AlongArc(start, ds, dtheta, 1.0);
  double fraction = 1.0;
  bool from_overlap = false;  // taken only when the step's end overlaps
  if (obstacles_.Overlaps(whole)) {
    // A step that starts overlapping (a spawn within the setup check's tolerance) may leave the
    // obstacle but not go deeper into it (PlanarObstacles::OverlapsFrom).
    from_overlap = obstacles_.Overlaps(start);
    const auto blocked_at = [&](const msgs::Pose2D& pose) {
      return from_overlap ? obstacles_.OverlapsFrom(start, pose) : obstacles_.Overlaps(pose);
    };
    if (!from_overlap || blocked_at(whole)) {
      double clear = 0.0, blocked = 1.0;
      for (int i = 0; i < 20; ++i) {
        const double mid = (clear + blocked) / 2.0;
        (blocked_at(AlongArc(start, ds, dtheta, mid)) ? blocked : clear) = mid;
      }
      fraction = clear;
    }
  }
  msgs::Pose2D end = fraction == 1.0 ? whole : AlongArc(start, ds, dtheta, fraction);
  // Stopped by a wall, the rest of the step's turn still happens where the footprint can be
  // pushed clear of what it touches by no more than the turn swings it (its reach times the
  // angle): a robot pressed against a wall turns, sliding away from it as its corners swing
  // round, as it does on the floor, where the contact pushes it and the tires scrub sideways.
  // The push is wheel slip: the wheels turn by the turn alone. The rest is the turn of the wheels'
  // differential part (their common part is what the wall stopped): with unequal radii the common
  // part turns the robot too, but only while it rolls, so a robot pressed straight into a wall
  // does not turn while its wheels, stopped, report no turn. With equal radii, the rest of dtheta.
  bool turned = false;
  const double rest_rad =
      (1.0 - fraction) * half_diff * (ids_.left_radius_m + ids_.right_radius_m) * dt / ids_.track_m;
  // fraction < 1 only after the bisection, i.e. with from_overlap taken.
  if (fraction < 1.0 && rest_rad != 0.0 && !from_overlap) {
    msgs::Pose2D slid = end;
    slid.theta_rad += rest_rad;
    if (obstacles_.PushOut(&slid, obstacles_.reach_m() * std::abs(rest_rad) + 1e-8)) {
      end = slid;
      turned = true;
    }
  }
  WriteUprightPose(end, q);
  mjtNum* base_v = d->qvel + ids_.base_dof;
  base_v[0] = fraction * v * std::cos(end.theta_rad);  // world frame
  base_v[1] = fraction * v * std::sin(end.theta_rad);
  base_v[2] = 0.0;
  base_v[3] = 0.0;  // body frame; upright, so its z is the world's
  base_v[4] = 0.0;
  base_v[5] = fraction * yaw_rate + (turned ? rest_rad / dt : 0.0);
  // The wheels: the straight part's speed kept by the fraction gone, the turning part's whole
  // when the turn was (their turn through the true radii is then the base's).
  const double left = turned ? fraction * s - half_diff : fraction * w_left;
  const double right = turned ? fraction * s + half_diff : fraction * w_right;
  d->qvel[left_dof_] = left;
  d->qvel[right_dof_] = right;
  d->qpos[left_qpos_] += left * dt;
  d->qpos[right_qpos_] += right * dt;
  d->time += dt;
}

}  // namespace plywood::sim
