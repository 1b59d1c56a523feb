#pragma once

#include <mujoco/mujoco.h>

#include <string>
#include <vector>

#include "msgs/pose2d.h"
#include "sim/world/planar_obstacles.h"

namespace plywood::sim {

// Where the planar drive reads and writes a scene's state in mjModel / mjData.
struct PlanarDriveIndices {
  int base_body = -1, base_qpos = -1, base_dof = -1;
  int left_joint = -1, right_joint = -1;
  int left_motor = -1, right_motor = -1;
  double left_radius_m = 0.0, right_radius_m = 0.0, track_m = 0.0;  // as built (E_d, E_b)
};

// One step of DriveMode::kPlanar: the robot moved without mj_step.
//
// Wheel speeds. A velocity servo drives each wheel with torque g kv (u - g w) (gear g, gain kv,
// command u clamped to ctrlrange) plus the joint's damping -c w. Rolling without slip, the robot's
// kinetic energy in the wheel speeds' mean s = (wl + wr) / 2 and half difference d = (wr - wl) / 2
// is Is s^2 + Id d^2 (the two wheels' share each, (1/2) I w^2 per wheel) with
//   Is = Iw + m r^2 / 2       (straight: each wheel carries half the robot's mass m),
//   Id = Iw + 2 Iz r^2 / b^2  (turning: half the yaw inertia Iz about the axle midpoint, through
//                              the lever b / 2 of track b),
// Iw a wheel's inertia about its axle plus the joint's armature, r the wheels' mean radius; so
// Is ds/dt = k (s* - s) and Id dd/dt = k (d* - d) with k = g^2 kv + c and s*, d* the commanded
// speeds' mean and half difference divided by g: first-order lags with time constants Is / k and
// Id / k (the generalised forces of s and d are the two wheels' torques' sum and difference). m, Iz
// (every robot body's mass and inertia about the base's vertical axis) and Iw come from the
// compiled model at the spawn pose; a step advances the lags as MuJoCo's explicit Euler integrator
// does (s += dt k / Is (s* - s), the factor capped at 1), so the wheels answer a command step as
// they do on the floor (PlanarDriveTest.WheelsAnswerACommandStepAsOnTheFloor); the body there slips
// behind them while it accelerates, which is not modelled.
//
// Pose. Wheel angles advance by w dt (semi-implicit, as mj_step), the base along the exact arc of
// v = (rr wr + rl wl) / 2 and yaw rate (rr wr - rl wl) / b with the as-built radii and track, so
// E_d and E_b act on the truth and not on the encoders. qpos (base pose, upright, its height
// unchanged; wheel angles), qvel (base velocity, wheel speeds) and time are written; nothing else
// of mjData is touched (Scene places the bodies when something asks).
//
// Walls. When the footprint at the step's end would overlap an obstacle (PlanarObstacles), the
// robot goes the largest fraction of the step's arc that stays clear (found to 2^-20 by
// bisection), the wheels turn by the same fraction and keep that fraction of their speed: the
// robot stops at the wall, its wheels stall with it, as on the floor with a friction that holds.
// A step that starts with the footprint in an obstacle (a spawn within the setup check's 1 mm, a
// PlaceRobot) may back out of it, turn or slide along it, but not bring the base origin closer to
// it (PlanarObstacles::OverlapsFrom). A NaN or huge command (after the ctrlrange clamp) zeroes
// both commands for the step and raises mjWARN_BADCTRL, as mj_step does. A step stopped by a wall
// still takes the rest of its turn where the footprint, turned, can be pushed clear of what it
// touches by translations of no more than the turn swings it (PlanarObstacles::PushOut): a robot
// pressed against a wall turns on the spot, sliding back as its corners swing round (the push is
// wheel slip; the wheels turn by the turn). Not modelled: wheel slip otherwise, the caster, tire
// scrub on turns, pushing, rebound, and sliding along a wall while driving (the blocked part of a
// step's forward motion is lost).
class PlanarDrive {
 public:
  // @pre mj_forward has run on `data` (the robot at its spawn pose).
  // @throws ConfigError naming `robot_file` when the wheels' actuators are not velocity servos or
  // the robot has no bumper_ring mesh.
  PlanarDrive(const mjModel* model, const mjData* data, const PlanarDriveIndices& indices,
              const std::string& robot_file);

  void Step(const mjModel* model, mjData* data);

  // Bearings (robot frame) of the footprint's points within skin_m of an obstacle at X_WR.
  void ContactBearings(const msgs::Pose2D& X_WR, double skin_m, std::vector<double>* out) {
    obstacles_.ContactBearings(X_WR, skin_m, out);
  }

  double straight_time_constant_s() const { return straight_inertia_ / stiffness_; }
  double turn_time_constant_s() const { return turn_inertia_ / stiffness_; }
  double stiffness() const { return stiffness_; }
  double command_gain() const { return command_gain_; }
  PlanarObstacles& obstacles() { return obstacles_; }
  const PlanarObstacles& obstacles() const { return obstacles_; }

 private:
  PlanarDriveIndices ids_;
  int left_qpos_ = -1, right_qpos_ = -1, left_dof_ = -1, right_dof_ = -1;
  double straight_inertia_ = 0.0, turn_inertia_ = 0.0;
  double stiffness_ = 0.0;     // k = g^2 kv + damping
  double command_gain_ = 0.0;  // g kv / k: the steady wheel speed per unit command
  double ctrl_lo_ = -1e300, ctrl_hi_ = 1e300;
  PlanarObstacles obstacles_;
};

}  // namespace plywood::sim
